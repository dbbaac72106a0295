# Start-up is most of a small conversion. Ceres (static already) pulls in glog, gflags,
# SuiteSparse, LAPACK/BLAS/ATLAS and through them libstdc++.so, libgfortran and a dozen
# more shared objects, and resolving and relocating their symbols would be a large share of
# every start of mocapfill-full (docs/performance.md). Only the verbs that fit PCA models run
# Ceres, yet every process would pay for it. A target with MOCAPFILL_STATIC_SOLVER_DEPS set
# links the static archives instead; the libraries' own consumers (tests) keep the shared
# ones. When any archive is missing, nothing changes.
#
#   mocapfill_link_solver_deps_statically(<target>)

function(mocapfill_archive_of out name)
  find_file(_archive_${name} NAMES lib${name}.a PATHS /usr/lib/x86_64-linux-gnu NO_CACHE)
  if(NOT _archive_${name})
    # Compiler runtime archives (libgfortran, libquadmath, libgomp) live beside gcc.
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=lib${name}.a
                    OUTPUT_VARIABLE _path OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(IS_ABSOLUTE "${_path}" AND EXISTS "${_path}")
      set(_archive_${name} "${_path}")
    endif()
  endif()
  set(${out} "${_archive_${name}}" PARENT_SCOPE)
endfunction()

function(mocapfill_link_solver_deps_statically target)
  if(NOT TARGET Ceres::ceres OR MOCAPFILL_SANITIZE)
    return()
  endif()
  # Link order: users before what they use. metis and libunwind ship no usable archive
  # (none, or one built without -fPIC); both are small C libraries and stay shared. glog's
  # stack traces need libunwind, but libunwind also exports the _Unwind_* functions C++
  # exceptions go through, at two sigprocmask calls per frame (480 for --version): libgcc's
  # unwinder is linked in first, so the executable defines those itself.
  set(names glog gflags spqr cholmod amd camd ccolamd colamd suitesparseconfig cxsparse
            lapack blas f77blas atlas gfortran quadmath gomp)
  set(archives)
  foreach(name IN LISTS names)
    mocapfill_archive_of(archive ${name})
    if(NOT archive)
      message(STATUS "mocapfill: lib${name}.a not found; ${target} links Ceres's dependencies shared")
      return()
    endif()
    list(APPEND archives "${archive}")
  endforeach()
  find_library(_metis NAMES metis libmetis.so.5 PATHS /usr/lib/x86_64-linux-gnu NO_CACHE)
  find_library(_unwind NAMES unwind libunwind.so.8 PATHS /usr/lib/x86_64-linux-gnu NO_CACHE)
  mocapfill_archive_of(_gcc_eh gcc_eh)
  if(NOT _metis OR NOT _unwind OR NOT _gcc_eh)
    message(STATUS "mocapfill: metis, libunwind or libgcc_eh not found; ${target} links Ceres's dependencies shared")
    return()
  endif()
  list(APPEND archives "${_metis}" "${_gcc_eh}" "${_unwind}" Threads::Threads m)

  # Ceres::ceres's dependencies become conditional on the consuming target's property.
  get_target_property(deps Ceres::ceres INTERFACE_LINK_LIBRARIES)
  set(flag "$<BOOL:$<TARGET_PROPERTY:MOCAPFILL_STATIC_SOLVER_DEPS>>")
  set(conditional)
  foreach(dep IN LISTS deps)
    if(dep STREQUAL "Eigen3::Eigen" OR dep STREQUAL "Threads::Threads")
      list(APPEND conditional "${dep}")
    else()
      list(APPEND conditional "$<$<NOT:${flag}>:${dep}>")
    endif()
  endforeach()
  foreach(archive IN LISTS archives)
    list(APPEND conditional "$<${flag}:${archive}>")
  endforeach()
  set_target_properties(Ceres::ceres PROPERTIES INTERFACE_LINK_LIBRARIES "${conditional}")
  set_target_properties(${target} PROPERTIES MOCAPFILL_STATIC_SOLVER_DEPS ON)
endfunction()

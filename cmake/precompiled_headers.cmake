# Precompiled headers. Most files include Eigen; every test includes GoogleTest and many
# nlohmann/json; every CLI verb includes CLI11, which alone takes seconds to parse. Parsing
# them once per class of targets rather than once per file makes a clean build much shorter
# (docs/performance.md).
# Three owner targets hold the headers, and every target of ours reuses its class's one
# (mocapfill_apply_precompiled_headers, called once all targets exist). Shared libraries and
# plug-ins hide their symbols, which takes different flags, so they compile without.
option(MOCAPFILL_PCH "Precompile the common third-party headers" ON)

set(MOCAPFILL_PCH_STD <algorithm> <array> <cmath> <cstdint> <functional> <map> <memory> <optional>
    <string> <string_view> <utility> <vector>)

function(mocapfill_add_pch_owner name)
  cmake_parse_arguments(ARG "" "" "HEADERS;LIBS" ${ARGN})
  add_library(${name} STATIC ${PROJECT_SOURCE_DIR}/cmake/pch_anchor.cc)
  target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  target_precompile_headers(${name} PRIVATE ${MOCAPFILL_PCH_STD} ${ARG_HEADERS})
  mocapfill_set_warnings(${name})
endfunction()

# Which owner a target reuses: tests/ linking GoogleTest -> test headers, converter/ -> CLI headers, the rest -> Eigen.
function(mocapfill_apply_precompiled_headers)
  if(NOT MOCAPFILL_PCH)
    return()
  endif()
  mocapfill_add_pch_owner(mocapfill_pch_core HEADERS <Eigen/Core> <Eigen/Geometry> LIBS Eigen3::Eigen)
  set(cli_libs Eigen3::Eigen nlohmann_json::nlohmann_json)
  if(TARGET CLI11::CLI11)
    list(APPEND cli_libs CLI11::CLI11)
  endif()
  mocapfill_add_pch_owner(mocapfill_pch_cli HEADERS <Eigen/Core> <Eigen/Geometry> <CLI/CLI.hpp>
                          <nlohmann/json.hpp> LIBS ${cli_libs})
  if(MOCAPFILL_BUILD_TESTS)
    mocapfill_add_pch_owner(mocapfill_pch_tests HEADERS <Eigen/Core> <Eigen/Geometry> <gtest/gtest.h>
                            <nlohmann/json.hpp> LIBS Eigen3::Eigen nlohmann_json::nlohmann_json GTest::gtest)
  endif()
  get_property(targets GLOBAL PROPERTY MOCAPFILL_TARGETS)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    get_target_property(dir ${target} SOURCE_DIR)
    if(type MATCHES "^(MODULE|SHARED)_LIBRARY$" OR target MATCHES "^mocapfill_pch_")
      continue()
    endif()
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
    # The test headers' PCH carries GoogleTest's compile definitions: only for targets linking it.
    get_target_property(libs ${target} LINK_LIBRARIES)
    if(rel MATCHES "^tests" AND "GTest::gtest" IN_LIST libs)
      if(MOCAPFILL_BUILD_TESTS)
        target_precompile_headers(${target} REUSE_FROM mocapfill_pch_tests)
      endif()
    elseif(rel MATCHES "^converter")
      target_precompile_headers(${target} REUSE_FROM mocapfill_pch_cli)
    else()
      target_precompile_headers(${target} REUSE_FROM mocapfill_pch_core)
    endif()
  endforeach()
endfunction()

// The Python module mocapfill._mocapfill: the public C++ API (include/mocapfill/) as Python,
// clips as numpy arrays. mocapfill/__init__.py adds the report dict and keyword defaults.
// Long calls release the GIL; errors become mocapfill.Error subclasses carrying the
// command-line tool's exit code.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "mocapfill/mocapfill.h"

namespace py = pybind11;
namespace api = mocapfill::api;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The Python exception classes, one per exit-code class, all under mocapfill.Error.
struct ErrorTypes {
  py::object base, usage, input, processing, output;
};

ErrorTypes& Errors() {
  static ErrorTypes* types = new ErrorTypes();  // lives as long as the interpreter
  return *types;
}

void RaiseError(const api::Error& e) {
  ErrorTypes& t = Errors();
  py::object type = e.kind() == api::ErrorKind::kUsage          ? t.usage
                    : e.kind() == api::ErrorKind::kInvalidInput ? t.input
                    : e.kind() == api::ErrorKind::kOutput       ? t.output
                                                                : t.processing;
  py::object instance = type(e.what());
  instance.attr("exit_code") = e.exit_code();
  PyErr_SetObject(type.ptr(), instance.ptr());
}

// frames x (width * joints) as a (frames, joints, width) array.
py::array_t<double> PerJoint(const api::RowMatrix& m, int width) {
  const py::ssize_t frames = m.rows(), joints = m.cols() / width;
  py::array_t<double> out({frames, joints, static_cast<py::ssize_t>(width)});
  std::copy(m.data(), m.data() + m.size(), out.mutable_data());
  return out;
}

// A (frames, joints, width) or (frames, width * joints) array as frames x (width * joints).
api::RowMatrix FromPerJoint(const Array& a, int width, const char* field) {
  if (a.ndim() == 3 && a.shape(2) == width) {
    api::RowMatrix m(a.shape(0), a.shape(1) * width);
    std::copy(a.data(), a.data() + a.size(), m.data());
    return m;
  }
  if (a.ndim() == 2 && a.shape(1) % width == 0) {
    api::RowMatrix m(a.shape(0), a.shape(1));
    std::copy(a.data(), a.data() + a.size(), m.data());
    return m;
  }
  throw api::Error(api::ErrorKind::kUsage, std::string(field) + ": expected shape (frames, joints, " +
                                               std::to_string(width) + ")");
}

api::RowMatrix FromMatrix(const Array& a, int width, const char* field) {
  if (a.ndim() != 2 || a.shape(1) != width)
    throw api::Error(api::ErrorKind::kUsage, std::string(field) + ": expected shape (joints, " + std::to_string(width) + ")");
  api::RowMatrix m(a.shape(0), width);
  std::copy(a.data(), a.data() + a.size(), m.data());
  return m;
}

py::array_t<double> ToArray(const Eigen::VectorXd& v) {
  py::array_t<double> out(v.size());
  std::copy(v.data(), v.data() + v.size(), out.mutable_data());
  return out;
}

Eigen::VectorXd FromArray(const Array& a, const char* field) {
  if (a.ndim() != 1) throw api::Error(api::ErrorKind::kUsage, std::string(field) + ": expected a 1-D array");
  return Eigen::Map<const Eigen::VectorXd>(a.data(), a.size());
}

api::Clip MakeClip(const Array& times, const Array& rotations, const std::optional<Array>& translations,
                   std::vector<std::vector<int>> rotation_keys, std::vector<std::vector<int>> translation_keys,
                   std::string name, double rate_hz) {
  api::Clip clip;
  clip.name = std::move(name);
  clip.rate_hz = rate_hz;
  clip.times_s = FromArray(times, "times");
  clip.rotations = FromPerJoint(rotations, 4, "rotations");
  if (translations) clip.translations = FromPerJoint(*translations, 3, "translations");
  clip.rotation_keys = std::move(rotation_keys);
  clip.translation_keys = std::move(translation_keys);
  return clip;
}

void BindScene(py::module_& m) {
  py::class_<api::Clip>(m, "Clip", "One animation, sampled: frame f at times[f]. Rotations are local unit "
                                   "quaternions (x, y, z, w); translations local, in metres.")
      .def(py::init(&MakeClip), py::arg("times"), py::arg("rotations"), py::arg("translations") = py::none(),
           py::arg("rotation_keys") = std::vector<std::vector<int>>{},
           py::arg("translation_keys") = std::vector<std::vector<int>>{}, py::arg("name") = "",
           py::arg("rate_hz") = 30.0)
      .def_readwrite("name", &api::Clip::name)
      .def_readwrite("rate_hz", &api::Clip::rate_hz)
      .def_property(
          "times", [](const api::Clip& c) { return ToArray(c.times_s); },
          [](api::Clip& c, const Array& a) { c.times_s = FromArray(a, "times"); })
      .def_property(
          "rotations", [](const api::Clip& c) { return PerJoint(c.rotations, 4); },
          [](api::Clip& c, const Array& a) { c.rotations = FromPerJoint(a, 4, "rotations"); },
          "(frames, joints, 4) local rotations, x y z w")
      .def_property(
          "translations", [](const api::Clip& c) { return PerJoint(c.translations, 3); },
          [](api::Clip& c, const Array& a) { c.translations = FromPerJoint(a, 3, "translations"); },
          "(frames, joints, 3) local translations (m)")
      .def_property_readonly(
          "root_translation",
          [](const api::Clip& c) {
            py::array_t<double> out({static_cast<py::ssize_t>(c.translations.rows()), py::ssize_t{3}});
            for (Eigen::Index f = 0; f < c.translations.rows(); ++f)
              for (int k = 0; k < 3; ++k) out.mutable_at(f, k) = c.translations(f, k);
            return out;
          },
          "(frames, 3) translation of the first joint (the root)")
      .def_readwrite("rotation_keys", &api::Clip::rotation_keys, "per joint: the frames its rotation is keyed at")
      .def_readwrite("translation_keys", &api::Clip::translation_keys)
      .def_property_readonly("frame_count", [](const api::Clip& c) { return c.times_s.size(); });

  py::class_<api::Scene>(m, "Scene", "A character and its animations (metres, Y up).")
      .def(py::init<>())
      .def_static(
          "from_skeleton",
          [](const std::vector<std::string>& names, const std::vector<int>& parents, const Array& rest_translations,
             const Array& rest_rotations) {
            return api::Scene::FromSkeleton(names, parents, FromMatrix(rest_translations, 3, "rest_translations"),
                                            FromMatrix(rest_rotations, 4, "rest_rotations"));
          },
          py::arg("names"), py::arg("parents"), py::arg("rest_translations"), py::arg("rest_rotations"))
      .def_property_readonly("joint_count", &api::Scene::joint_count)
      .def_property_readonly("joint_names", &api::Scene::joint_names)
      .def_property_readonly("joint_parents", &api::Scene::joint_parents)
      .def_property_readonly("rest_translations", &api::Scene::rest_translations)
      .def_property_readonly("rest_rotations", &api::Scene::rest_rotations)
      .def_property_readonly("clip_count", &api::Scene::clip_count)
      .def_property_readonly("clips",
                             [](const api::Scene& s) {
                               std::vector<api::Clip> clips;
                               for (int i = 0; i < s.clip_count(); ++i) clips.push_back(s.clip(i));
                               return clips;
                             })
      .def("clip", &api::Scene::clip, py::arg("index") = 0)
      .def("set_clip", &api::Scene::set_clip, py::arg("index"), py::arg("clip"))
      .def("add_clip", [](api::Scene& s, const api::Clip& c) { s.set_clip(s.clip_count(), c); }, py::arg("clip"))
      .def("clear_clips", &api::Scene::clear_clips)
      .def_property_readonly("mesh_count", &api::Scene::mesh_count)
      .def_property_readonly("source_format", &api::Scene::source_format)
      .def_property_readonly("warnings", &api::Scene::warnings)
      .def("__repr__", [](const api::Scene& s) {
        return "<mocapfill.Scene: " + std::to_string(s.joint_count()) + " joints, " + std::to_string(s.clip_count()) +
               " clips>";
      });
}

void BindIo(py::module_& m) {
  const auto release = py::call_guard<py::gil_scoped_release>();
  m.def(
      "load",
      [](const std::string& path, const std::string& unit, const std::string& up, double rate_hz,
         const std::string& animation, bool strict) {
        return api::Load(path, {unit, up, rate_hz, animation, strict});
      },
      release, py::arg("path"), py::arg("unit") = "auto", py::arg("up") = "auto", py::arg("rate_hz") = 0.0,
      py::arg("animation") = "", py::arg("strict") = false, "Reads .bvh, .gltf, .glb, .fbx (and Assimp's formats).");
  m.def(
      "save",
      [](const api::Scene& scene, const std::string& path, const std::string& unit, bool pretty,
         const std::string& gltf_skeleton, const std::string& bvh_layout) {
        api::Save(scene, path, {unit, pretty, gltf_skeleton, bvh_layout});
      },
      release, py::arg("scene"), py::arg("path"), py::arg("unit") = "auto", py::arg("pretty") = true,
      py::arg("gltf_skeleton") = "skin", py::arg("bvh_layout") = "source",
      "Writes .gltf, .glb or .bvh by the extension; atomic. gltf_skeleton: skin, mesh or nodes; "
      "bvh_layout: source or standard.");
  m.def(
      "convert",
      [](const std::string& input, const std::string& output, const std::string& unit, const std::string& up,
         const std::string& gltf_skeleton, const std::string& bvh_layout) {
        api::Convert(input, output, {unit, up, 0.0, "", false}, {"auto", true, gltf_skeleton, bvh_layout});
      },
      release, py::arg("input"), py::arg("output"), py::arg("unit") = "auto", py::arg("up") = "auto",
      py::arg("gltf_skeleton") = "skin", py::arg("bvh_layout") = "source");
}

void BindDatabase(py::module_& m) {
  py::class_<api::Database>(m, "Database", "A motion capture database (.mfdb, motion files/folders, or the default).")
      .def_static(
          "open",
          [](const std::vector<std::string>& paths, double rate_hz, const std::string& map, int threads,
             const std::string& unit, const std::string& up, bool mirror,
             const std::function<void(size_t, size_t)>& progress) {
            api::ImportProgress report;
            if (progress) {
              // Worker threads call back; the GIL is taken for the Python callable.
              report = [progress](size_t done, size_t total) {
                py::gil_scoped_acquire gil;
                try {
                  progress(done, total);
                } catch (py::error_already_set& e) {
                  e.discard_as_unraisable("mocapfill.Database.open progress");
                }
              };
            }
            py::gil_scoped_release release;
            return api::Database::Open(paths, {rate_hz, map, threads, unit, up, mirror}, report);
          },
          py::arg("paths"), py::arg("rate_hz") = 30.0, py::arg("map") = "", py::arg("threads") = 0,
          py::arg("unit") = "auto", py::arg("up") = "auto", py::arg("mirror") = false, py::arg("progress") = nullptr)
      .def("save", &api::Database::Save, py::call_guard<py::gil_scoped_release>(), py::arg("path"))
      .def_property_readonly("name", &api::Database::name)
      .def_property_readonly("rate_hz", &api::Database::rate_hz)
      .def_property_readonly("frame_count", &api::Database::frame_count)
      .def_property_readonly("clip_count", &api::Database::clip_count)
      .def_property_readonly("clip_names", &api::Database::clip_names)
      .def_property_readonly("joint_names", &api::Database::joint_names)
      .def("__repr__", [](const api::Database& d) {
        return "<mocapfill.Database " + d.name() + ": " + std::to_string(d.clip_count()) + " clips, " +
               std::to_string(d.frame_count()) + " frames>";
      });

  m.def("default_database_path", &api::DefaultDatabasePath,
        "Where the default database is read from (the installation's share/mocapfill/default_db).");

  py::class_<api::PcaModel>(m, "PcaModel", "The PCA model of a database (for the pca and hybrid methods).")
      .def_static(
          "build",
          [](const api::Database& db, double variance_kept, int max_components, std::vector<std::string> labels) {
            return api::PcaModel::Build(db, {variance_kept, max_components, std::move(labels)});
          },
          py::call_guard<py::gil_scoped_release>(), py::arg("database"), py::arg("variance_kept") = 0.95,
          py::arg("max_components") = 30, py::arg("labels") = std::vector<std::string>{})
      .def_static("open", &api::PcaModel::Open, py::call_guard<py::gil_scoped_release>(), py::arg("path"))
      .def("save", &api::PcaModel::Save, py::call_guard<py::gil_scoped_release>(), py::arg("path"))
      .def_property_readonly("component_count", &api::PcaModel::component_count)
      .def_property_readonly("variances", &api::PcaModel::variances);
}

void BindMethods(py::module_& m) {
  m.def(
      "_fill",
      [](const api::Scene& sketch, const api::Database& db, const api::FillOptions& options) {
        api::FillResult r;
        {
          py::gil_scoped_release release;
          r = api::Fill(sketch, db, options);
        }
        return py::make_tuple(std::move(r.scene), r.report_json);
      },
      py::arg("sketch"), py::arg("database"), py::arg("options"));
  py::class_<api::FillOptions>(m, "_FillOptions")
      .def(py::init<>())
      .def_readwrite("method", &api::FillOptions::method)
      .def_readwrite("map", &api::FillOptions::map)
      .def_readwrite("rest", &api::FillOptions::rest)
      .def_readwrite("output_rate_hz", &api::FillOptions::output_rate_hz)
      .def_readwrite("keep", &api::FillOptions::keep)
      .def_readwrite("synthesize", &api::FillOptions::synthesize)
      .def_readwrite("position_keys", &api::FillOptions::position_keys)
      .def_readwrite("plant_feet", &api::FillOptions::plant_feet)
      .def_readwrite("texture", &api::FillOptions::texture)
      .def_readwrite("coverage", &api::FillOptions::coverage)
      .def_readwrite("threads", &api::FillOptions::threads)
      .def_readwrite("more", &api::FillOptions::more)
      .def_property(
          "pca_model", [](const api::FillOptions& o) { return o.pca_model; },
          [](api::FillOptions& o, const api::PcaModel* model) { o.pca_model = model; }, py::keep_alive<1, 2>());
  m.def(
      "retarget",
      [](const api::Scene& motion, const api::Scene& character, std::map<std::string, std::string> map,
         const std::string& rest, std::map<std::string, std::string> character_map, const std::string& character_rest) {
        return api::Retarget(motion, character, {std::move(map), rest}, {std::move(character_map), character_rest});
      },
      py::call_guard<py::gil_scoped_release>(), py::arg("motion"), py::arg("character"),
      py::arg("map") = std::map<std::string, std::string>{}, py::arg("rest") = "auto",
      py::arg("character_map") = std::map<std::string, std::string>{}, py::arg("character_rest") = "auto",
      "motion's clips on character's rig, in character's scene.");
  m.def(
      "filter",
      [](const api::Scene& scene, std::vector<double> gains, double residual_gain, int levels,
         std::vector<std::string> joints) {
        return api::Filter(scene, {std::move(gains), residual_gain, levels, std::move(joints)});
      },
      py::call_guard<py::gil_scoped_release>(), py::arg("scene"), py::arg("gains"), py::arg("residual_gain") = 1.0,
      py::arg("levels") = 0, py::arg("joints") = std::vector<std::string>{},
      "Multiresolution filtering: a gain per frequency band, highest first.");
  m.def(
      "_run_pipeline",
      [](const std::string& path, const std::vector<std::string>& sets) {
        api::PipelineResult r;
        {
          py::gil_scoped_release release;
          r = api::RunPipeline(path, sets);
        }
        return py::make_tuple(r.report_json, r.warnings);
      },
      py::arg("path"), py::arg("sets") = std::vector<std::string>{});
  m.def("describe_pipeline", &api::DescribePipeline, py::call_guard<py::gil_scoped_release>(), py::arg("path"),
        py::arg("sets") = std::vector<std::string>{},
        "The validated plan of a pipeline file, one node per line (as `mocapfill run --dry-run`).");
  m.def("pipeline_node_types", &api::PipelineNodeTypes, "Every pipeline node type with its options.");
}

}  // namespace

PYBIND11_MODULE(_mocapfill, m) {
  m.doc() = "mocapfill: motion capture conversion, retargeting, filtering and sketch filling";
  m.attr("__version__") = MOCAPFILL_VERSION_STRING;
  ErrorTypes& t = Errors();
  t.base = py::reinterpret_steal<py::object>(PyErr_NewException("mocapfill.Error", PyExc_RuntimeError, nullptr));
  const auto sub = [&](const char* name) {
    return py::reinterpret_steal<py::object>(PyErr_NewException(name, t.base.ptr(), nullptr));
  };
  t.usage = sub("mocapfill.UsageError");
  t.input = sub("mocapfill.InputError");
  t.processing = sub("mocapfill.ProcessingError");
  t.output = sub("mocapfill.OutputError");
  m.attr("Error") = t.base;
  m.attr("UsageError") = t.usage;
  m.attr("InputError") = t.input;
  m.attr("ProcessingError") = t.processing;
  m.attr("OutputError") = t.output;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const api::Error& e) {
      RaiseError(e);
    }
  });
  BindScene(m);
  BindIo(m);
  BindDatabase(m);
  BindMethods(m);
}

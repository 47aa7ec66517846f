// illum._illum: the library's API for Python. Pictures come back as NumPy arrays; the GIL is
// released while a picture is drawn; errors are illum.InputError (a ValueError: the command line's
// message) and illum.Error. python/illum/__init__.py turns keyword arguments into options.
#include <illum/illum.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <exception>
#include <mutex>

namespace py = pybind11;

namespace {

// A vector handed to NumPy without a copy: the array owns it.
template <typename T>
py::array_t<T> arrayOf(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), free);
}

// What to draw: a path ("" for the built-in scene), a Model, or ("json", text, base_dir).
illum::Source sourceOf(const py::object& source) {
  if (py::isinstance<illum::Model>(source)) return illum::Source(source.cast<const illum::Model&>());
  if (py::isinstance<py::tuple>(source)) {
    const auto t = source.cast<py::tuple>();
    return illum::Source::sceneJson(t[1].cast<std::string>(), t[2].cast<std::string>());
  }
  return illum::Source(source.cast<std::string>());
}

// Runs `draw` without the GIL. The progress callback (or none) is called with the GIL from the
// rendering threads; Ctrl+C or an exception in the callback cancels the render and is raised here.
template <typename Draw>
illum::Picture withoutGil(const py::object& progress, bool linear, Draw draw) {
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  std::exception_ptr raised;
  illum::RenderSettings settings;
  settings.linear = linear;
  settings.cancel = &cancel;
  settings.progress = [&](double fraction) {
    if (cancel) return;
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(fraction);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!raised) raised = std::current_exception();
      cancel = true;
    }
  };
  illum::Picture picture;
  try {
    py::gil_scoped_release release;
    picture = draw(settings);
  } catch (const illum::Error&) {
    if (!raised) throw;
  }
  if (raised) std::rethrow_exception(raised);
  return picture;
}

py::tuple arrays(illum::Picture&& p) {
  const py::ssize_t h = p.height, w = p.width;
  py::object linear = py::none();
  if (!p.linear.empty()) linear = arrayOf(std::move(p.linear), {h, w, 4});
  return py::make_tuple(arrayOf(std::move(p.rgba), {h, w, 4}), linear, p.warnings);
}

}  // namespace

PYBIND11_MODULE(_illum, m) {
  m.doc() = "illum's library: the lighting models of computer graphics, rendered exactly on the CPU";
  static py::exception<illum::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<illum::InputError> inputError(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const illum::InputError& e) {
      inputError(e.what());
    } catch (const illum::Error& e) {
      error(e.what());
    }
  });

  m.attr("__version__") = illum::version();

  py::class_<illum::Model>(m, "Model", "A model file read once, to be drawn many times")
      .def_property_readonly("path", &illum::Model::path)
      .def_property_readonly("vertex_count", &illum::Model::vertexCount)
      .def_property_readonly("triangle_count", &illum::Model::triangleCount)
      .def_property_readonly("material_count", &illum::Model::materialCount)
      .def_property_readonly("texture_count", &illum::Model::textureCount)
      .def_property_readonly("bounds", [](const illum::Model& model) { return py::make_tuple(model.boundsMin(), model.boundsMax()); })
      .def_property_readonly("warnings", &illum::Model::warnings)
      .def_property_readonly("vertices", [](const illum::Model& model) {
        std::vector<float> p = model.positions();
        const py::ssize_t n = py::ssize_t(p.size() / 3);
        return arrayOf(std::move(p), {n, 3});
      }, "Every vertex in world space, N×3 float32")
      .def_property_readonly("faces", [](const illum::Model& model) {
        std::vector<std::uint32_t> t = model.triangles();
        const py::ssize_t n = py::ssize_t(t.size() / 3);
        return arrayOf(std::move(t), {n, 3});
      }, "Three indices into vertices per triangle, M×3 uint32")
      .def("__repr__", [](const illum::Model& model) {
        return "<illum.Model " + model.path() + ": " + std::to_string(model.triangleCount()) + " triangles>";
      });

  m.def("load_model", [](const std::string& path, const illum::Options& options) {
    py::gil_scoped_release release;
    return illum::loadModel(path, options);
  }, py::arg("path"), py::arg("options"));

  m.def("render", [](const py::object& source, const illum::Options& options, bool linear, const py::object& progress) {
    const illum::Source s = sourceOf(source);
    return arrays(withoutGil(progress, linear, [&](const illum::RenderSettings& settings) {
      return illum::render(s, options, settings);
    }));
  }, py::arg("source"), py::arg("options"), py::arg("linear"), py::arg("progress"));

  m.def("compare", [](const py::object& source, const illum::Options& options) {
    const illum::Source s = sourceOf(source);
    return arrays(withoutGil(py::none(), false, [&](const illum::RenderSettings&) { return illum::compare(s, options); }));
  }, py::arg("source"), py::arg("options"));

  m.def("history", [](const py::object& source, const illum::Options& options) {
    const illum::Source s = sourceOf(source);
    return arrays(withoutGil(py::none(), false, [&](const illum::RenderSettings&) { return illum::history(s, options); }));
  }, py::arg("source"), py::arg("options"));

  m.def("evaluate_json", [](const illum::Options& options) { return illum::evaluateJson(options); }, py::arg("options"));

  m.def("encode_png", [](py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> rgba) {
    if (rgba.ndim() != 3 || rgba.shape(2) != 4) throw py::value_error("encode_png: expected an H×W×4 uint8 array");
    illum::Picture p;
    p.height = int(rgba.shape(0));
    p.width = int(rgba.shape(1));
    p.rgba.assign(rgba.data(), rgba.data() + rgba.size());
    const std::vector<std::uint8_t> png = p.png();
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
  }, py::arg("rgba"));
}

// The Python module `hyst`: the library's models, inverses, signals, file formats, fitters and
// model registry, with numpy arrays in and out. See python/tests for the whole API in use.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/core/progress.hpp"
#include "hyst/io/limits.hpp"

#ifndef HYST_VERSION
#define HYST_VERSION "unknown"
#endif

namespace hyst::python {

namespace {

void require_bounded_size(py::ssize_t size, std::string_view name) {
  if (static_cast<std::size_t>(size) > io::limits::kMaxNumpyValues) {
    throw Error(fmt::format("{} has {} values, more than the limit of {} values of one array", name,
                            size, io::limits::kMaxNumpyValues));
  }
}

}  // namespace

std::span<const double> as_span(const InputArray& array, std::string_view name) {
  if (array.ndim() != 1) {
    throw Error(
        fmt::format("{} must be a one-dimensional array, got {} dimensions", name, array.ndim()));
  }
  require_bounded_size(array.size(), name);
  return {array.data(), static_cast<std::size_t>(array.shape(0))};
}

InputArray as_bounded_array(const py::object& value, std::string_view name) {
  if (value.is_none()) throw Error(fmt::format("{} is missing (None); expected an array", name));
  // Its size as it stands (a numpy array is not copied here), before a conversion to float64.
  const auto array = py::array::ensure(value);
  if (!array) throw Error(fmt::format("{} is not an array of numbers", name));
  require_bounded_size(array.size(), name);
  return value.cast<InputArray>();
}

std::vector<double> as_vector(const InputArray& array, std::string_view name) {
  const auto values = as_span(array, name);
  return {values.begin(), values.end()};
}

py::array_t<double> to_array(std::vector<double>&& values) {
  auto owned = std::make_unique<std::vector<double>>(std::move(values));
  const auto size = static_cast<py::ssize_t>(owned->size());
  const double* data = owned->data();
  py::capsule owner(owned.get(),
                    [](void* pointer) { delete static_cast<std::vector<double>*>(pointer); });
  owned.release();  // the capsule owns it now
  return py::array_t<double>({size}, {static_cast<py::ssize_t>(sizeof(double))}, data, owner);
}

py::array_t<double> readonly_view(std::span<const double> values, py::handle owner) {
  py::array_t<double> array({static_cast<py::ssize_t>(values.size())},
                            {static_cast<py::ssize_t>(sizeof(double))}, values.data(), owner);
  array.attr("setflags")("write"_a = false);
  return array;
}

py::array_t<double> readonly_copy(std::span<const double> values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  array.attr("setflags")("write"_a = false);
  return array;
}

std::string format_list(std::span<const double> values) {
  constexpr std::size_t kShown = 8;
  std::string text = "[";
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values.size() > kShown && k == kShown - 2) {
      text += fmt::format(", ..., {}", values.back());
      break;
    }
    text += fmt::format("{}{}", k ? ", " : "", values[k]);
  }
  return text + "]";
}

// A Python callable as a ProgressCallback, called with the GIL taken (the run releases it).
ProgressCallback progress_callback(const py::object& progress) {
  if (progress.is_none()) return {};
  // Shared, so that copies of the callback never touch Python reference counts without the GIL.
  std::shared_ptr<py::object> callable(new py::object(progress), [](py::object* object) {
    py::gil_scoped_acquire gil;
    delete object;
  });
  return [callable](const Progress& report) {
    py::gil_scoped_acquire gil;
    (*callable)(report.done, report.total, std::string(report.current));
  };
}

py::object json_to_python(const nlohmann::json& value) {
  using Type = nlohmann::json::value_t;
  switch (value.type()) {
    case Type::boolean:
      return py::bool_(value.get<bool>());
    case Type::number_integer:
      return py::int_(value.get<std::int64_t>());
    case Type::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case Type::number_float:
      return py::float_(value.get<double>());
    case Type::string:
      return py::str(value.get_ref<const std::string&>());
    case Type::array: {
      py::list list;
      for (const auto& item : value)
        list.append(json_to_python(item));
      return list;
    }
    case Type::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items())
        dict[py::str(key)] = json_to_python(item);
      return dict;
    }
    default:  // null, binary, discarded
      return py::none();
  }
}

namespace {

nlohmann::json json_at_depth(py::handle value, const std::string& path, std::size_t depth);

}  // namespace

nlohmann::json python_to_json(py::handle value, const std::string& path) {
  return json_at_depth(value, path, 0);
}

namespace {

nlohmann::json json_at_depth(py::handle value, const std::string& path, std::size_t depth) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    try {
      return value.cast<std::int64_t>();
    } catch (const py::cast_error&) {
      return value.cast<std::uint64_t>();
    }
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::array>(value)) {
    return json_at_depth(value.attr("tolist")(), path, depth);
  }
  const bool container = py::isinstance<py::dict>(value) || py::isinstance<py::list>(value) ||
                         py::isinstance<py::tuple>(value);
  if (container && depth >= io::limits::kMaxJsonDepth) {
    // A list that contains itself would recurse for ever, a very deep one end the stack.
    throw Error(fmt::format("{}: nested deeper than {} levels (the limit of hyst's JSON values)",
                            path.empty() ? "<value>" : path.substr(0, 200),
                            io::limits::kMaxJsonDepth));
  }
  if (py::isinstance<py::dict>(value)) {
    auto object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) {
        throw Error(fmt::format("{}: key {} is not a string", path.empty() ? "<dict>" : path,
                                py::repr(key).cast<std::string>()));
      }
      const auto name = key.cast<std::string>();
      object[name] = json_at_depth(item, path.empty() ? name : path + "." + name, depth + 1);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    auto array = nlohmann::json::array();
    std::size_t index = 0;
    for (const auto& item : value)
      array.push_back(json_at_depth(item, fmt::format("{}[{}]", path, index++), depth + 1));
    return array;
  }
  if (py::isinstance(value, py::module_::import("numpy").attr("generic"))) {
    return json_at_depth(value.attr("item")(), path, depth);  // numpy scalar
  }
  throw Error(fmt::format("{}: a {} cannot be stored as JSON", path.empty() ? "<value>" : path,
                          py::type::of(value).attr("__name__").cast<std::string>()));
}

}  // namespace

}  // namespace hyst::python

// The extension hyst._core; the package hyst (python/hyst/__init__.py) re-exports it. Named
// "hyst" before anything is bound, so that classes and submodules are hyst.Model, hyst.io, ...
PYBIND11_MODULE(_core, module) {
  namespace py = pybind11;
  module.attr("__name__") = "hyst";
  module.doc() =
      "The bindings of hyst: every registered model by name (hyst.models(), hyst.Model, "
      "hyst.fit, hyst.fit_records, hyst.compare), the typed operators and models (play, stop, "
      "relay, PI, GPI, Preisach, ...) with their inverses, the butterfly strain and FORC fits, "
      "actuators in closed loop (hyst.ActuatorConfig), C export (hyst.export_c), test signals "
      "(hyst.signals), data files (hyst.io: CSV, MAT, aixACCT, MicroMag, MagIC) and record "
      "processing (hyst.data).\n\n"
      "Invalid input (parameters, files, NaN samples) raises hyst.Error; numpy float64 arrays "
      "are used in place, and returned arrays own their memory (no copies).\n\n"
      "State: models and inverses never change when they run. simulate() and invert() start "
      "from a state passed in or, without one, from the object's start state (initial_state() "
      "for the typed classes; Model.state, the model file's state, for hyst.Model and its "
      "inverse). What advances is a separate running object: a typed model's State (passed to "
      "step/simulate/invert), or the ModelRunner / InverseRunner of Model.runner() / "
      "Inverse.runner(). State dicts are values, read and never written; "
      "Model.simulate(..., return_state=True) also returns the final state.";
  module.attr("__version__") = HYST_VERSION;

  // hyst::Error -> hyst.Error (an Exception) with the message, and the offending parameter field
  // (e.g. "thresholds[3]") as `.field`, None when the error is not about one field.
  static PyObject* error_type =
      PyErr_NewExceptionWithDoc("hyst.Error",
                                "Invalid user input: parameters, files or data. The message names "
                                "the quantity, index and value; .field names the parameter.",
                                PyExc_Exception, nullptr);
  if (!error_type) throw py::error_already_set();
  module.add_object("Error", py::handle(error_type));
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const hyst::Error& error) {
      // Messages quote file content, which need not be UTF-8 (a binary file read as CSV):
      // undecodable bytes become U+FFFD instead of a UnicodeDecodeError hiding the error.
      const auto text = [](const std::string& bytes) {
        PyObject* decoded =
            PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "replace");
        if (!decoded) throw py::error_already_set();
        return py::reinterpret_steal<py::str>(decoded);
      };
      py::object instance =
          py::reinterpret_borrow<py::object>(error_type)(text(std::string(error.what())));
      instance.attr("field") =
          error.field().empty() ? py::object(py::none()) : py::object(text(error.field()));
      PyErr_SetObject(error_type, instance.ptr());
    } catch (const hyst::python::OutOfMemory& error) {
      PyErr_SetString(PyExc_MemoryError, error.what());
    }
  });

  hyst::python::bind_operators(module);
  hyst::python::bind_models(module);
  hyst::python::bind_signals(module);
  hyst::python::bind_io(module);
  hyst::python::bind_identify(module);
  hyst::python::bind_registry(module);
  hyst::python::bind_actuator(module);
  hyst::python::bind_data(module);
  hyst::python::bind_compare(module);
  hyst::python::bind_magnetometer_files(module);
  hyst::python::bind_forc(module);
  hyst::python::bind_butterfly(module);
  hyst::python::bind_dynamics(module);
}

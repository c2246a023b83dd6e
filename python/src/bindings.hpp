#pragma once
// Shared helpers of the Python module `hyst`: numpy conversion without copies where possible,
// JSON <-> Python objects, and one bind_* function per area of the library.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <nlohmann/json.hpp>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fitted_domain.hpp"

namespace hyst::python {

namespace py = pybind11;
using namespace pybind11::literals;

//! The text of a return annotation, as a template argument (Typed below).
template <std::size_t N>
struct Annotation {
  constexpr Annotation(const char (&text)[N]) { std::copy_n(text, N, value); }  // NOLINT
  char value[N];
};
//! A dict, tuple, list or object returned under the annotation `Name` in the signature line
//! (pybind11 writes "-> dict" for a py::dict): "Dict[str, Any]", "Tuple[numpy.ndarray[...],
//! hyst.InverseReport]". The stubs (python/stubgen/make_stubs.py) and inspect.signature() read it.
template <class Base, Annotation Name>
struct Typed : Base {
  Typed() = default;
  Typed(Base object) : Base(std::move(object)) {}  // NOLINT: implicit, from what a binding built
};
//! A dict keyed by names (columns, fields, files) with values of several types.
using StrDict = Typed<py::dict, "Dict[str, Any]">;
//! Columns by name: {name: float64 array}.
using ArrayDict = Typed<py::dict, "Dict[str, numpy.ndarray[numpy.float64]]">;
//! A list of float64 arrays.
using ArrayList = Typed<py::list, "List[numpy.ndarray[numpy.float64]]">;
//! What an inversion returns: (inputs, InverseReport).
using InvertResult = Typed<py::tuple, "Tuple[numpy.ndarray[numpy.float64], hyst.InverseReport]">;
//! (input, output) arrays.
using ArrayPair =
    Typed<py::tuple, "Tuple[numpy.ndarray[numpy.float64], numpy.ndarray[numpy.float64]]">;

//! The default of unbounded keyword arguments (input_min, output_max...).
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

//! Any 1-D sequence of numbers: a float64 C-contiguous numpy array is used in place, anything
//! else (lists, other dtypes, strided views) is converted once by numpy.
using InputArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

//! The samples of a one-dimensional array; throws hyst::Error naming `name` for other shapes and
//! for more values than io::limits::kMaxNumpyValues (the limit of files).
std::span<const double> as_span(const InputArray& array, std::string_view name);
//! `value` as a float64 array of any dimension, checked before anything is copied: hyst::Error
//! naming `name` for None ("input is missing (None)") and for more values than
//! io::limits::kMaxNumpyValues.
InputArray as_bounded_array(const py::object& value, std::string_view name);

//! Raised as Python's MemoryError with its message: an allocation that failed while the library
//! built something the message names, with its size.
struct OutOfMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};
//! `build()`, with a std::bad_alloc turned into OutOfMemory "out of memory while <what>".
template <class Build>
decltype(auto) naming_failed_allocation(std::string_view what, Build&& build) {
  try {
    return build();
  } catch (const std::bad_alloc&) {
    throw OutOfMemory("out of memory while " + std::string(what));
  }
}
//! The samples copied into a vector (for parameters, which the models keep).
std::vector<double> as_vector(const InputArray& array, std::string_view name);
//! A Python callable progress(done, total, current) as a ProgressCallback (empty for None),
//! called with the GIL taken from a run that released it.
ProgressCallback progress_callback(const py::object& progress);

//! A writeable float64 array that takes over the vector's memory (no copy); a capsule frees it.
py::array_t<double> to_array(std::vector<double>&& values);
//! A read-only float64 view of memory owned by `owner` (kept alive by the array).
py::array_t<double> readonly_view(std::span<const double> values, py::handle owner);
//! A read-only float64 copy: a snapshot that cannot be mistaken for a handle to live state.
py::array_t<double> readonly_copy(std::span<const double> values);

//! {'inside': bool, 'message': str} of a check on a record of `samples` samples (DomainCheck).
py::dict domain_check_dict(const DomainCheck& check, std::size_t samples);

//! "[0, 0.3, 0.7]", shortened to the first and last values for long sequences.
std::string format_list(std::span<const double> values);

//! JSON -> dict / list / float / int / str / bool / None.
py::object json_to_python(const nlohmann::json& value);
//! The reverse (also numpy arrays and scalars); throws hyst::Error naming `path` for anything
//! JSON cannot hold.
nlohmann::json python_to_json(py::handle value, const std::string& path);

void bind_operators(py::module_& module);
void bind_models(py::module_& module);
void bind_signals(py::module_& module);
void bind_io(py::module_& module);
void bind_identify(py::module_& module);
void bind_registry(py::module_& module);
void bind_dynamics(py::module_& module);
void bind_actuator(py::module_& module);
void bind_data(py::module_& module);
void bind_compare(py::module_& module);
void bind_magnetometer_files(py::module_& module);
void bind_forc(py::module_& module);
void bind_butterfly(py::module_& module);

//! A record's samples as given from Python, copied.
struct PythonCurve {
  std::vector<double> input;
  std::vector<double> output;
};
//! (input, output) pairs of arrays, copied; errors name `what`[n] ("curves[2] must be a pair").
std::vector<PythonCurve> curves_from_python(const py::sequence& sequence, std::string_view what);

}  // namespace hyst::python

namespace pybind11::detail {
template <class Base, hyst::python::Annotation Name>
struct handle_type_name<hyst::python::Typed<Base, Name>> {
  static constexpr auto name = const_name(Name.value);
};
}  // namespace pybind11::detail

#include "hyst/registry/state_space_file.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst {
namespace {

constexpr std::string_view kStateSpaceModelName = "state_space";

// An array of rows, each an array of numbers, all rows alike; an empty array is a matrix with no
// row (and no column). Every row's length is checked before the matrix is allocated, so that it
// holds no more numbers than the file does (a first row of 10^7 numbers and 10^7 empty rows must
// not ask for 10^14).
Eigen::MatrixXd json_matrix(const nlohmann::json& value, const std::string& path) {
  if (!value.is_array())
    throw Error(
        fmt::format("{}: expected an array of rows, got {}", path, detail::describe_json(value)));
  const auto rows = Eigen::Index(value.size());
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto& row = value[std::size_t(i)];
    const auto row_path = fmt::format("{}[{}]", path, i);
    if (!row.is_array())
      throw Error(fmt::format("{}: expected a row (an array of numbers), got {}", row_path,
                              detail::describe_json(row)));
    if (row.size() != value[0].size())
      throw Error(fmt::format("{}: {} numbers, but row 0 has {}; every row must be as long",
                              row_path, row.size(), value[0].size()));
  }
  const auto columns = rows == 0 ? Eigen::Index(0) : Eigen::Index(value[0].size());
  Eigen::MatrixXd matrix(rows, columns);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < columns; ++j)
      matrix(i, j) = detail::json_number(value[std::size_t(i)][std::size_t(j)],
                                         fmt::format("{}[{}][{}]", path, i, j));
  return matrix;
}

Eigen::MatrixXd matrix_field(detail::JsonFields& fields, std::string_view key) {
  const auto* value = fields.raw(key);
  if (!value) throw Error(fmt::format("{}: missing field", fields.path_of(key)));
  return json_matrix(*value, fields.path_of(key));
}

nlohmann::json matrix_json(const Eigen::MatrixXd& matrix) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < matrix.cols(); ++j)
      row.push_back(matrix(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

StateSpace state_space_from_params(const nlohmann::json& value, const std::string& path) {
  detail::JsonFields fields(value, path);
  StateSpace::Params p;
  p.sample_time = fields.number("sample_time");
  p.a = matrix_field(fields, "a");
  p.b = matrix_field(fields, "b");
  p.c = matrix_field(fields, "c");
  p.d = matrix_field(fields, "d");
  fields.finish();
  // With no state, "b": [] has no row to tell the input count; D does (see the header).
  if (p.a.rows() == 0 && p.b.rows() == 0) p.b.resize(0, p.d.cols());
  try {
    return StateSpace(std::move(p));
  } catch (const Error& error) {
    detail::rethrow_at(error, path);
  }
}

nlohmann::json state_space_params_to_json(const StateSpace& model) {
  const auto& p = model.params();
  return {{"sample_time", p.sample_time},
          {"a", matrix_json(p.a)},
          {"b", matrix_json(p.b)},
          {"c", matrix_json(p.c)},
          {"d", matrix_json(p.d)}};
}

namespace {

Eigen::VectorXd state_vector_from_json(const nlohmann::json& value, const StateSpace& model) {
  detail::JsonFields fields(value, "state");
  const auto numbers = fields.numbers("x");
  fields.finish();
  try {
    return model
        .make_state(Eigen::Map<const Eigen::VectorXd>(numbers.data(), Eigen::Index(numbers.size())))
        .x;
  } catch (const Error& error) {
    detail::rethrow_at(error, "state");
  }
}

}  // namespace

StateSpaceFile state_space_from_json(const nlohmann::json& document, std::string_view source) {
  try {
    if (!document.is_object())
      throw Error(fmt::format("expected a JSON object, got {}", detail::describe_json(document)));
    detail::JsonFields fields(document, "");
    const auto name = fields.string("model");
    if (name != kStateSpaceModelName)
      throw Error(fmt::format("model: \"{}\" is not a state-space model file (expected \"{}\")",
                              name, kStateSpaceModelName));
    require_model_file_version(fields.raw("version"));
    const auto* params = fields.raw("params");
    if (!params) throw Error("params: missing field");
    const auto* state = fields.raw("state");
    const auto* info = fields.raw("info");
    if (info && !info->is_object())
      throw Error(fmt::format("info: expected an object, got {}", detail::describe_json(*info)));
    fields.finish();
    StateSpace model = state_space_from_params(*params, "params");
    std::optional<Eigen::VectorXd> x;
    if (state) x = state_vector_from_json(*state, model);
    return {std::move(model), std::move(x), info ? *info : nlohmann::json::object()};
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", source, error.what()));
  }
}

nlohmann::json state_space_to_json(const StateSpace& model,
                                   const std::optional<Eigen::VectorXd>& state,
                                   const nlohmann::json& info) {
  nlohmann::json document = {{"model", std::string(kStateSpaceModelName)},
                             {"version", kModelFileVersion},
                             {"params", state_space_params_to_json(model)}};
  if (state) {
    const Eigen::VectorXd x = model.make_state(*state).x;  // a file that loads again
    document["state"] = {{"x", std::vector<double>(x.data(), x.data() + x.size())}};
  }
  if (!info.empty()) document["info"] = info;
  return document;
}

StateSpaceFile load_state_space(const std::filesystem::path& path) {
  const nlohmann::json document = io::parse_json_text(io::read_file(path), path.string());
  return state_space_from_json(document, path.string());
}

void save_state_space(const std::filesystem::path& path, const StateSpace& model,
                      const std::optional<Eigen::VectorXd>& state, const nlohmann::json& info) {
  io::write_file_atomically(path, state_space_to_json(model, state, info).dump(2) + "\n");
}

}  // namespace hyst

#pragma once
// One table per parameter or fit-options struct: each field's JSON name, the member it fills, its
// unit and meaning, and whether a file may leave it out. Reading (errors name the field), writing,
// and the schema that `hyst models NAME`, Python's ModelEntry and the docs show are derived from
// the table, so that a field is described once; the CLI's --option and Python's keyword arguments
// reach the fitters as JSON read by the same table.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "../detail/json_fields.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst::detail {

enum class Presence {
  required,  // a file must give the field
  optional,  // left out, the member keeps the struct's default (shown in the schema)
};

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

// The schema type of a field of C++ type T.
template <class T>
constexpr std::string_view field_type_name() {
  if constexpr (std::is_same_v<T, bool>) {
    return "boolean";
  } else if constexpr (std::is_same_v<T, std::size_t>) {
    return "whole number";
  } else if constexpr (std::is_same_v<T, std::string> || std::is_enum_v<T>) {
    return "string";
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    return "array of numbers";
  } else if constexpr (std::is_same_v<T, std::vector<std::size_t>>) {
    return "array of whole numbers";
  } else if constexpr (IsOptional<T>::value) {
    return field_type_name<typename T::value_type>();
  } else {
    static_assert(std::is_same_v<T, double>, "no JSON form for this member type");
    return "number";
  }
}

// A field's value in JSON (enumerations by their to_string(), found by argument-dependent lookup).
template <class T>
nlohmann::json field_to_json(const T& value) {
  if constexpr (IsOptional<T>::value) {
    return value ? field_to_json(*value) : nlohmann::json();
  } else if constexpr (std::is_enum_v<T>) {
    return std::string(to_string(value));
  } else {
    return value;
  }
}

// A default value as the schema shows it: "" for an unset optional or an empty list, whose
// meaning the field's description gives.
template <class T>
std::string default_text(const T& value) {
  if constexpr (IsOptional<T>::value) {
    return value ? default_text(*value) : std::string();
  } else if constexpr (std::is_same_v<T, std::vector<double>> ||
                       std::is_same_v<T, std::vector<std::size_t>>) {
    return value.empty() ? std::string() : fmt::format("[{}]", fmt::join(value, ", "));
  } else if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_enum_v<T>) {
    return std::string(to_string(value));
  } else {
    return fmt::format("{}", value);
  }
}

template <class S>
class FieldTable {
 public:
  using Reader = std::function<void(JsonFields&, S&)>;
  using Writer = std::function<void(const S&, nlohmann::json&)>;

  // `presence`: of the fields added without one (fit options may all be left out); `defaults`:
  // the values of the fields left out, which the schema shows.
  explicit FieldTable(Presence presence = Presence::required, S defaults = S{})
      : default_presence_(presence), defaults_(std::move(defaults)) {}

  // A member of type double, std::size_t, bool, std::string, std::vector<double> or
  // std::optional<double> (optional: left out means unset; written only when set).
  template <class T>
  FieldTable& add(std::string_view name, T S::*member, std::string_view unit,
                  std::string_view description) {
    return add(name, member, unit, description, default_presence_);
  }
  template <class T>
  FieldTable& add(std::string_view name, T S::*member, std::string_view unit,
                  std::string_view description, Presence presence) {
    if constexpr (IsOptional<T>::value) presence = Presence::optional;
    const std::string key(name);
    add_field(
        info_of<T>(name, member, unit, description, presence), presence,
        [key, member](JsonFields& fields, S& target) {
          target.*member = read_value<T>(fields, key);
        },
        [key, member](const S& source, nlohmann::json& json) {
          write_value(source.*member, key, json);
        });
    return *this;
  }

  // An enumeration E or std::optional<E>, written by to_string() and read by `parse` (a
  // hyst::Error of `parse` gets the field's path in front).
  template <class M, class E>
  FieldTable& add(std::string_view name, M S::*member, E (*parse)(std::string_view),
                  std::string_view description) {
    return add(name, member, parse, description, default_presence_);
  }
  template <class M, class E>
  FieldTable& add(std::string_view name, M S::*member, E (*parse)(std::string_view),
                  std::string_view description, Presence presence) {
    static_assert(std::is_same_v<M, E> || std::is_same_v<M, std::optional<E>>);
    if constexpr (IsOptional<M>::value) presence = Presence::optional;
    const std::string key(name);
    add_field(
        info_of<M>(name, member, "", description, presence), presence,
        [key, member, parse](JsonFields& fields, S& target) {
          target.*member = fields.parsed(key, parse);
        },
        [key, member](const S& source, nlohmann::json& json) {
          write_value(source.*member, key, json);
        });
    return *this;
  }

  // A list of objects, each read and written by `element_table` (which must outlive this table),
  // e.g. starting points of a fit; left out, the list keeps its default.
  template <class T>
  FieldTable& add(std::string_view name, std::vector<T> S::*member,
                  const FieldTable<T>& element_table, std::string_view description) {
    const std::string key(name);
    const auto* elements = &element_table;
    add_field(
        {key, "array of objects", "", std::string(description), {}}, Presence::optional,
        [key, member, elements](JsonFields& fields, S& target) {
          const auto& list = *fields.raw(key);
          const auto path = fields.path_of(key);
          if (!list.is_array()) {
            throw Error(
                fmt::format("{}: expected an array of objects, got {}", path, describe_json(list)));
          }
          (target.*member).clear();
          for (std::size_t i = 0; i < list.size(); ++i) {
            (target.*member).push_back(elements->read(list[i], fmt::format("{}[{}]", path, i)));
          }
        },
        [key, member, elements](const S& source, nlohmann::json& json) {
          if ((source.*member).empty()) return;
          auto list = nlohmann::json::array();
          for (const auto& element : source.*member)
            list.push_back(elements->write(element));
          json[key] = std::move(list);
        });
    return *this;
  }

  // Every field of `inner`, a table of the member struct N, read into and written from that
  // member: a file's flat fields for a struct that nests another.
  template <class N>
  FieldTable& add_all(N S::*outer, const FieldTable<N>& inner) {
    for (const auto& field : inner.fields_) {
      add_field(
          field.info, field.presence,
          [outer, read = field.read](JsonFields& fields, S& target) {
            read(fields, target.*outer);
          },
          [outer, write = field.write](const S& source, nlohmann::json& json) {
            write(source.*outer, json);
          });
      if (field.applies) {
        only_if([outer, applies = field.applies](const S& s) { return applies(s.*outer); },
                field.unused_when);
      }
    }
    return *this;
  }

  // The field added last exists only where `applies` holds for the fields before it (e.g. the
  // parameters of one density kind): elsewhere it is neither read nor written, and a file that
  // gives it is refused with "<path>: not used <unused_when>".
  FieldTable& only_if(std::function<bool(const S&)> applies, std::string unused_when) {
    fields_.back().applies = std::move(applies);
    fields_.back().unused_when = std::move(unused_when);
    return *this;
  }

  // A field with its own JSON form (e.g. bounds keyed by parameter name); `read` is called only
  // when the field is present or required, `write` may leave the JSON unchanged.
  FieldTable& add_custom(ParameterInfo info, Presence presence, Reader read, Writer write) {
    add_field(std::move(info), presence, std::move(read), std::move(write));
    return *this;
  }

  // Reads every field of the table into `target` (fields left out keep its values); finish() of
  // `fields` is the caller's, so that a struct may be read with a few fields of its own.
  void read_into(JsonFields& fields, S& target) const {
    for (const auto& field : fields_) {
      if (field.applies && !field.applies(target)) {
        if (fields.has(field.info.name)) {
          throw Error(
              fmt::format("{}: not used {}", fields.path_of(field.info.name), field.unused_when));
        }
        continue;
      }
      if (field.presence == Presence::optional && !fields.has(field.info.name)) continue;
      field.read(fields, target);
    }
  }
  // `json` read into the defaults; any field the table does not know is an error
  // ("fit options.operatorz: unknown field (known: ...)").
  S read(const nlohmann::json& json, std::string path) const {
    JsonFields fields(json, std::move(path));
    S target = defaults_;
    read_into(fields, target);
    fields.finish();
    return target;
  }
  nlohmann::json write(const S& source) const {
    auto json = nlohmann::json::object();
    for (const auto& field : fields_) {
      if (!field.applies || field.applies(source)) field.write(source, json);
    }
    return json;
  }
  // The documented fields in table order, with the defaults of the optional ones.
  std::vector<ParameterInfo> schema() const {
    std::vector<ParameterInfo> schema;
    for (const auto& field : fields_)
      schema.push_back(field.info);
    return schema;
  }

 private:
  template <class>
  friend class FieldTable;

  struct Field {
    ParameterInfo info;
    Presence presence;
    Reader read;
    Writer write;
    std::function<bool(const S&)> applies = {};  // empty: always
    std::string unused_when = {};
  };

  template <class T>
  ParameterInfo info_of(std::string_view name, T S::*member, std::string_view unit,
                        std::string_view description, Presence presence) {
    ParameterInfo info{std::string(name),
                       std::string(field_type_name<T>()),
                       std::string(unit),
                       std::string(description),
                       {}};
    if (presence == Presence::optional) info.default_value = default_text(defaults_.*member);
    return info;
  }

  template <class T>
  static T read_value(JsonFields& fields, const std::string& key) {
    if constexpr (std::is_same_v<T, bool>) {
      return fields.boolean(key);
    } else if constexpr (std::is_same_v<T, std::size_t>) {
      return fields.count(key);
    } else if constexpr (std::is_same_v<T, std::string>) {
      return fields.string(key);
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      return fields.numbers(key);
    } else if constexpr (std::is_same_v<T, std::vector<std::size_t>>) {
      return fields.counts(key);
    } else {
      return fields.number(key);  // double, or the value of an optional<double>
    }
  }

  // An unset optional is left out of the JSON.
  template <class T>
  static void write_value(const T& value, const std::string& key, nlohmann::json& json) {
    if constexpr (IsOptional<T>::value) {
      if (!value) return;
    }
    json[key] = field_to_json(value);
  }

  void add_field(ParameterInfo info, Presence presence, Reader read, Writer write) {
    fields_.push_back({std::move(info), presence, std::move(read), std::move(write), {}, {}});
  }

  Presence default_presence_;
  S defaults_;
  std::vector<Field> fields_;
};

// The options of the shared multistart engine (src/identify/detail/multistart_fit.hpp) that the
// options struct O has, described alike for every fitter that runs on it.
template <class O>
FieldTable<O> add_multistart_options(FieldTable<O> table) {
  if constexpr (requires { &O::max_iterations; }) {
    table.add("max_iterations", &O::max_iterations, "",
              "Levenberg-Marquardt iterations of the best start");
  }
  if constexpr (requires { &O::screening_iterations; }) {
    table.add("screening_iterations", &O::screening_iterations, "",
              "iterations of every start before the best one goes on");
  }
  if constexpr (requires { &O::refined_starts; }) {
    table.add("refined_starts", &O::refined_starts, "",
              "screened starts that go on; the lowest final cost is kept");
  }
  if constexpr (requires { &O::function_tolerance; }) {
    table.add("function_tolerance", &O::function_tolerance, "",
              "relative cost change that ends the fit");
  }
  if constexpr (requires { &O::global_evaluations; }) {
    table.add("global_evaluations", &O::global_evaluations, "",
              "cost evaluations of the global search before the local starts, 0 = none");
  }
  return table;
}

// The options of the fits whose output is linear in play-operator weights (PI, modified PI,
// rate-dependent PI, PI with creep), described alike: the play grid, then the NNLS settings that
// the options struct O has.
template <class O>
FieldTable<O> add_play_weight_options(FieldTable<O> table) {
  table.add("operators", &O::operators, "", "number of plays when thresholds are not given")
      .add("thresholds", &O::thresholds, "input units", "fixed thresholds (default: uniform)");
  if constexpr (requires { &O::fit_offset; }) {
    table.add("fit_offset", &O::fit_offset, "", "fit the output offset");
  }
  if constexpr (requires { &O::min_linear_weight; }) {
    table.add("min_linear_weight", &O::min_linear_weight, "",
              "lower bound of p_0, keeps p_0 > 0 (the model invertible)");
  }
  return table;
}

// The options of the fits on a grid of levels over an input range (Preisach, KP, butterfly
// strain): `levels` as `levels_description` says, and the range, the data's by default.
template <class O>
FieldTable<O> add_grid_options(FieldTable<O> table, std::string levels_description) {
  return table.add("levels", &O::levels, "", std::move(levels_description))
      .add("lower", &O::lower, "input units", "grid range (default: the data's)")
      .add("upper", &O::upper, "input units", "grid range (default: the data's)");
}

}  // namespace hyst::detail

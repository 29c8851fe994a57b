#include "python_values.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/input_error.h"

namespace py = pybind11;

namespace swingsim::python {

py::object toPython(const Json& json) {
  switch (json.type()) {
    case Json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : json.items()) d[py::str(key)] = toPython(value);
      return std::move(d);
    }
    case Json::value_t::array: {
      py::list l;
      for (const auto& value : json) l.append(toPython(value));
      return std::move(l);
    }
    case Json::value_t::boolean: return py::bool_(json.get<bool>());
    case Json::value_t::number_integer: return py::int_(json.get<long long>());
    case Json::value_t::number_unsigned: return py::int_(json.get<unsigned long long>());
    case Json::value_t::number_float: {
      const double v = json.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());  // as the JSON file's null
    }
    case Json::value_t::string: return py::str(json.get<std::string>());
    default: return py::none();
  }
}

namespace {

py::object scalarToPython(const std::string& text) {
  if (text == "true") return py::bool_(true);
  if (text == "false") return py::bool_(false);
  if (!text.empty()) {
    char* end = nullptr;
    errno = 0;
    const long long whole = std::strtoll(text.c_str(), &end, 10);
    if (*end == '\0' && errno == 0) return py::int_(whole);
    const double number = std::strtod(text.c_str(), &end);
    if (*end == '\0') return py::float_(number);
  }
  return py::str(text);
}

void emit(YAML::Emitter& out, const py::handle& value, const std::string& where) {
  if (py::isinstance<py::dict>(value)) {
    out << YAML::BeginMap;
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      out << YAML::Key << py::str(key).cast<std::string>() << YAML::Value;
      emit(out, item, where + "." + py::str(key).cast<std::string>());
    }
    out << YAML::EndMap;
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    out << YAML::Flow << YAML::BeginSeq;
    for (const auto& item : value) emit(out, item, where + "[]");
    out << YAML::EndSeq;
  } else if (py::isinstance<py::bool_>(value) || py::isinstance(value, py::module_::import("numpy").attr("bool_"))) {
    out << (value.cast<bool>() ? "true" : "false");
  } else if (py::isinstance<py::str>(value)) {
    out << YAML::DoubleQuoted << value.cast<std::string>();
  } else if (py::hasattr(value, "__index__")) {
    out << py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  } else if (py::hasattr(value, "__float__")) {
    out << formatNumber(value.cast<double>());
  } else if (value.is_none()) {
    out << YAML::Null;
  } else {
    throw InputError(where + ": expected a number, text, list or mapping, found a Python " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
}

}  // namespace

py::object toPython(const YAML::Node& node) {
  if (node.IsMap()) {
    py::dict d;
    for (const auto& item : node) d[py::str(item.first.as<std::string>())] = toPython(item.second);
    return std::move(d);
  }
  if (node.IsSequence()) {
    py::list l;
    for (const auto& item : node) l.append(toPython(item));
    return std::move(l);
  }
  if (node.IsScalar()) return node.Tag() == "!" ? py::str(node.Scalar()) : scalarToPython(node.Scalar());
  return py::none();
}

std::string toYamlText(const py::handle& value, const std::string& where) {
  YAML::Emitter out;
  emit(out, value, where);
  return std::string(out.c_str()) + "\n";
}

}  // namespace swingsim::python

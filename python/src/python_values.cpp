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
    case Json::value_t::boolean:
      return py::bool_(json.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(json.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(json.get<unsigned long long>());
    case Json::value_t::number_float: {
      const double v = json.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());  // as the JSON file's null
    }
    case Json::value_t::string:
      return py::str(json.get<std::string>());
    default:
      return py::none();
  }
}

namespace {

bool isNumpy(const py::handle& value, const char* type) {
  return py::isinstance(value, py::module_::import("numpy").attr(type));
}

bool isBool(const py::handle& value) { return PyBool_Check(value.ptr()) || isNumpy(value, "bool_"); }

bool isInteger(const py::handle& value) {
  return !isBool(value) && (PyLong_Check(value.ptr()) || isNumpy(value, "integer"));
}

// np.float64 is a Python float; np.float32 is not.
bool isReal(const py::handle& value) {
  return isInteger(value) || PyFloat_Check(value.ptr()) || isNumpy(value, "floating");
}

[[noreturn]] void throwTypeError(const std::string& where, const std::string& expected, const py::handle& value) {
  throw py::type_error(formatArgumentProblem(where, expected, describePython(value)));
}

// A numpy array where the loaders expect a list or a number: a 1-D numeric one as its list,
// a 0-d one as its number; any other as a message naming `where`.
py::object numpyAsList(const py::handle& array, const std::string& where) {
  const int dimensions = array.attr("ndim").cast<int>();
  const std::string kind = py::str(array.attr("dtype").attr("kind")).cast<std::string>();
  if (dimensions > 1 || kind.size() != 1 || std::string("biuf").find(kind) == std::string::npos)
    throw InputError(where + ": expected a number or a 1-D array of numbers, found a " + describePython(array));
  return array.attr("tolist")();
}

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

// The deepest nesting a record's YAML takes (a knee file's is 5): a list that contains itself
// recursed without bound and crashed the interpreter.
constexpr int kMaxYamlDepth = 64;

void emit(YamlWriter& out, const py::handle& value, const std::string& where, int depth = 0) {
  if (depth > kMaxYamlDepth)
    throw InputError(where.substr(0, 200) + ": expected at most " + std::to_string(kMaxYamlDepth) +
                     " levels of lists and mappings (got deeper: a list or mapping that contains itself?)");
  if (py::isinstance<py::dict>(value)) {
    out.beginMap();
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      out.key(py::str(key).cast<std::string>());
      emit(out, item, where + "." + py::str(key).cast<std::string>(), depth + 1);
    }
    out.endMap();
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    out.beginList();
    for (const auto& item : value) emit(out, item, where + "[]", depth + 1);
    out.endList();
  } else if (py::isinstance<py::bool_>(value) || py::isinstance(value, py::module_::import("numpy").attr("bool_"))) {
    out.plain(value.cast<bool>() ? "true" : "false");
  } else if (isNumpy(value, "ndarray")) {
    emit(out, numpyAsList(value, where), where, depth + 1);
  } else if (py::isinstance<py::str>(value)) {
    out.quoted(value.cast<std::string>());
  } else if (py::hasattr(value, "__index__")) {
    out.plain(py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>());
  } else if (py::hasattr(value, "__float__")) {
    out.plain(formatNumber(value.cast<double>()));
  } else if (value.is_none()) {
    out.null();
  } else {
    throw InputError(where + ": expected a number, text, list or mapping, found a Python " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
}

}  // namespace

py::object toPython(const YamlTree& node) {
  if (node.isMap()) {
    py::dict d;
    for (const auto& [key, item] : node.entries()) d[py::str(key)] = toPython(item);
    return std::move(d);
  }
  if (node.isList()) {
    py::list l;
    for (const auto& item : node.items()) l.append(toPython(item));
    return std::move(l);
  }
  if (node.isScalar()) return node.isQuoted() ? py::str(node.scalar()) : scalarToPython(node.scalar());
  return py::none();
}

py::object yamlTextToPython(const std::string& text) {
  return toPython(YamlTree::parse(text, "yaml", "swingsim's own YAML"));
}

std::string toYamlText(const py::handle& value, const std::string& where) {
  YamlWriter out;
  emit(out, value, where);
  return out.text() + "\n";
}

std::string describePython(const py::handle& value) {
  if (value.is_none()) return "None";
  const py::handle type = py::type::of(value);
  const std::string module = py::str(type.attr("__module__")).cast<std::string>();
  std::string name = py::str(type.attr("__qualname__")).cast<std::string>();
  if (module != "builtins") name = module + "." + name;
  if (isNumpy(value, "ndarray")) return name + " of shape " + py::repr(value.attr("shape")).cast<std::string>();
  std::string text = py::repr(value).cast<std::string>();
  constexpr std::size_t kMaxShown = 80;  // a long list or dict is cut, not printed whole
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown) + "...";
  return name + " " + text;
}

long long readWholeArgument(const py::handle& value, const std::string& where, const WholeNumberRange& range) {
  if (!isInteger(value)) throwTypeError(where, "expected an integer", value);
  const py::object whole = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));  // numpy's too
  if (!whole) throw py::error_already_set();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(whole.ptr(), &overflow);
  if (overflow != 0 || !range.check(v).empty())
    throw InputError(formatArgumentProblem(where, range.expected, py::str(whole).cast<std::string>()));
  return v;
}

double readNumberArgument(const py::handle& value, const std::string& where, std::string (*check)(double)) {
  if (!isReal(value)) throwTypeError(where, "expected a number", value);
  const double v = PyFloat_AsDouble(value.ptr());  // an int beyond a double: OverflowError
  if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  const std::string bad = check ? check(v) : "";
  if (!bad.empty()) throw InputError(formatArgumentProblem(where, bad, py::repr(value).cast<std::string>()));
  return v;
}

std::optional<AddedMass> readAddedMassArguments(const py::object& mass, const py::object& below,
                                                const std::string& function) {
  if (mass.is_none() != below.is_none())
    throw py::type_error(function + ": added_mass_kg and added_mass_below_knee_m: give both or neither");
  if (mass.is_none()) return std::nullopt;
  // As the command line's --add-mass KG@M: neither negative (0 kg adds nothing; 0 m is at the knee).
  const auto notNegative = [](double v) { return v >= 0 ? std::string() : std::string("expected a value >= 0"); };
  return AddedMass{readNumberArgument(mass, function + ": added_mass_kg", notNegative),
                   readNumberArgument(below, function + ": added_mass_below_knee_m", notNegative)};
}

std::string readTextArgument(const py::handle& value, const std::string& where) {
  if (!py::isinstance<py::str>(value)) throwTypeError(where, "expected text (str)", value);
  return value.cast<std::string>();
}

std::string readChoiceArgument(const py::handle& value, const std::string& where,
                               const std::vector<std::string>& choices) {
  std::string expected = "expected one of";
  for (const std::string& c : choices) expected += (&c == &choices.front() ? " '" : ", '") + c + "'";
  if (!py::isinstance<py::str>(value)) throwTypeError(where, expected, value);
  const std::string text = value.cast<std::string>();
  for (const std::string& c : choices)
    if (c == text) return text;
  throw InputError(formatArgumentProblem(where, expected, py::repr(value).cast<std::string>()));
}

bool readFlagArgument(const py::handle& value, const std::string& where) {
  if (!isBool(value)) throwTypeError(where, "expected True or False", value);
  return value.cast<bool>();
}

bool isPathArgument(const py::handle& value) {
  return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

std::string readPathArgument(const py::handle& value, const std::string& where) {
  const char* expected = "expected a path (str or os.PathLike)";
  if (!isPathArgument(value)) throwTypeError(where, expected, value);
  const py::object path = py::module_::import("os").attr("fspath")(value);
  if (!py::isinstance<py::str>(path)) throwTypeError(where, expected, path);
  return path.cast<std::string>();
}

}  // namespace swingsim::python

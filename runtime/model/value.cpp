// Values and D3D initializer conversions.
#include <charconv>
#include <cmath>
#include <cstdio>

#include "fx/model/value.h"
#include "model_internal.h"

namespace fx {
namespace {

void flatten_bases(const Type& t, std::vector<BaseType>& out) {
  uint32_t n = t.element_count();
  for (uint32_t e = 0; e < n; ++e) {
    if (t.cls == TypeClass::structure && t.structure) {
      for (const StructMember& m : t.structure->members) flatten_bases(m.type, out);
    } else {
      for (uint32_t i = 0; i < t.element_components(); ++i) out.push_back(t.base);
    }
  }
}

std::string number_text(double v, BaseType base) {
  if (base == BaseType::boolean) return v != 0 ? "true" : "false";
  char buf[64];
  if (base == BaseType::int32 || base == BaseType::uint32) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  // The shortest spelling that reads back as the same value: a float parameter's 0.8 is
  // held as 0.800000011920929 and prints as 0.8, a double's as 0.8 only if it is 0.8.
  const std::to_chars_result r = base == BaseType::float64
                                     ? std::to_chars(buf, buf + sizeof buf, v)
                                     : std::to_chars(buf, buf + sizeof buf, static_cast<float>(v));
  return std::string(buf, r.ptr);
}

}  // namespace

double convert_component(double v, BaseType base) {
  switch (base) {
    case BaseType::boolean: return v != 0 ? 1 : 0;
    case BaseType::int32: {
      if (!std::isfinite(v)) return 0;
      double t = std::trunc(v);
      if (t > 2147483647.0 || t < -2147483648.0) t = std::fmod(t, 4294967296.0);
      if (t > 2147483647.0) t -= 4294967296.0;
      if (t < -2147483648.0) t += 4294967296.0;
      return t;
    }
    case BaseType::uint32: {
      if (!std::isfinite(v)) return 0;
      double t = std::fmod(std::trunc(v), 4294967296.0);
      return t < 0 ? t + 4294967296.0 : t;
    }
    case BaseType::half:
    case BaseType::float32: return static_cast<double>(static_cast<float>(v));
    case BaseType::float64: return v;
  }
  return v;
}

std::vector<float> Value::floats() const {
  std::vector<float> out;
  out.reserve(components.size());
  for (double c : components) out.push_back(static_cast<float>(c));
  return out;
}

std::vector<int32_t> Value::ints() const {
  std::vector<int32_t> out;
  out.reserve(components.size());
  for (double c : components)
    out.push_back(static_cast<int32_t>(static_cast<int64_t>(convert_component(c, BaseType::int32))));
  return out;
}

std::string Value::to_string() const {
  if (is_string()) {
    std::string s = "\"";
    for (char c : text) {
      if (c == '"' || c == '\\') s += '\\';
      s += c;
    }
    return s + "\"";
  }
  std::vector<BaseType> bases;
  flatten_bases(type, bases);
  auto comp = [&](size_t i) { return number_text(components[i], i < bases.size() ? bases[i] : type.base); };
  if (components.size() == 1 && !type.is_array()) return comp(0);
  std::string s;
  bool list = type.is_array() || type.cls == TypeClass::structure || !type.is_numeric();
  s = list ? "{" : type.to_string() + "(";
  for (size_t i = 0; i < components.size(); ++i) s += (i ? ", " : "") + comp(i);
  return s + (list ? "}" : ")");
}

Value make_scalar(BaseType base, double v) {
  Value out;
  out.type = make_numeric(base);
  out.components.push_back(convert_component(v, base));
  return out;
}

Value make_string(std::string text) {
  Value out;
  out.type.cls = TypeClass::string;
  out.text = std::move(text);
  return out;
}

std::optional<Value> convert_value(const Value& value, const Type& target, SourceRange where, DiagnosticSink& diags) {
  if (target.cls == TypeClass::string) {
    if (value.is_string()) return value;
    diags.error("initializer-mismatch", where, "cannot initialise a string with " + value.to_string());
    return std::nullopt;
  }
  if (!target.is_numeric() && target.cls != TypeClass::structure) {
    diags.error("initializer-mismatch", where, "a " + target.to_string() + " cannot take a constant initializer");
    return std::nullopt;
  }
  if (!value.is_numeric()) {
    diags.error("initializer-mismatch", where,
                "cannot initialise a " + target.to_string() + " with " + value.to_string());
    return std::nullopt;
  }
  const size_t want = target.component_count();
  const size_t have = value.components.size();
  Value out;
  out.type = target;
  if (have == 1 && !value.type.is_array()) {
    out.components.assign(want, value.components[0]);
  } else if (have == want) {
    out.components = value.components;
  } else if (have > want && value.type.is_numeric() && !value.type.is_array() && target.is_numeric() &&
             !target.is_array()) {
    diags.warning("truncated-initializer", where,
                  "implicit truncation of " + value.type.to_string() + " to " + target.to_string());
    if (value.type.cls == TypeClass::matrix && target.cls == TypeClass::matrix) {
      for (uint8_t r = 0; r < target.rows; ++r)
        for (uint8_t c = 0; c < target.cols; ++c) out.components.push_back(value.components[r * value.type.cols + c]);
    } else {
      out.components.assign(value.components.begin(), value.components.begin() + static_cast<long>(want));
    }
  } else {
    diags.error("initializer-mismatch", where,
                "a " + target.to_string() + " needs " + std::to_string(want) + " component" + (want == 1 ? "" : "s") +
                    ", the initializer has " + std::to_string(have));
    return std::nullopt;
  }
  std::vector<BaseType> bases;
  flatten_bases(target, bases);
  for (size_t i = 0; i < out.components.size() && i < bases.size(); ++i)
    out.components[i] = convert_component(out.components[i], bases[i]);
  return out;
}

}  // namespace fx

// HLSL spelling shared by the fixed-function generators: literals and parameter-bound values.
#include "fixed_function_hlsl.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace fx::ff_detail {
namespace {

bool is_integer_type(const std::string& t) {
  return t == "int" || t == "uint" || t == "dword" || t == "DWORD" || t == "bool";
}

// Components of a numeric HLSL type spelling ("float3" -> 3, "float" -> 1, "float4x4" -> 16).
int components_of(const std::string& t) {
  if (t.empty()) return 0;
  const size_t x = t.find('x');
  if (x != std::string::npos && x > 0 && std::isdigit(static_cast<unsigned char>(t[x - 1])))
    return (t[x - 1] - '0') * (x + 1 < t.size() ? t[x + 1] - '0' : 1);
  const char last = t.back();
  return std::isdigit(static_cast<unsigned char>(last)) ? last - '0' : 1;
}

// Whether a parameter can be redeclared and read as a whole: not an array element, struct or
// object (those keep the value the state resolved to).
bool readable(const ParameterRef& p) {
  return p.bound() && p.type.find_first_of("[ <") == std::string::npos && components_of(p.type) >= 1;
}

}  // namespace

std::string literal(float v) {
  if (!std::isfinite(v)) v = v > 0 ? 3.402823466e38f : (v < 0 ? -3.402823466e38f : 0.0f);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string literal4(const std::array<float, 4>& v) {
  return "float4(" + literal(v[0]) + ", " + literal(v[1]) + ", " + literal(v[2]) + ", " + literal(v[3]) + ")";
}

void Declarations::uniform(const std::string& type, const std::string& name) {
  if (!declared_.emplace(name, type).second) return;
  text_ += type + " " + name + ";\n";
}

std::string Declarations::vector(const FixedVector& v, const std::array<float, 4>& pad) {
  if (!readable(v.parameter)) return literal4(v.value);
  const std::string& t = v.parameter.type;
  const std::string& n = v.parameter.name;
  uniform(t, n);
  if (is_integer_type(t)) {  // a D3DCOLOR 0xAARRGGBB
    const std::string u = "uint(" + n + ")";
    return "(float4((" + u + " >> 16) & 255u, (" + u + " >> 8) & 255u, " + u + " & 255u, (" + u +
           " >> 24) & 255u) / 255.0)";
  }
  switch (components_of(t)) {
    case 1: return "float4(" + n + ", " + n + ", " + n + ", " + n + ")";
    case 2: return "float4(" + n + ", " + literal(pad[2]) + ", " + literal(pad[3]) + ")";
    case 3: return "float4(" + n + ", " + literal(pad[3]) + ")";
    case 4: return n;
    default: return "float4(" + n + "[0])";  // a matrix: its first row
  }
}

std::string Declarations::scalar(const FixedScalar& v) {
  if (!readable(v.parameter)) return literal(v.value);
  uniform(v.parameter.type, v.parameter.name);
  if (components_of(v.parameter.type) > 1) return "float(" + v.parameter.name + ".x)";
  return "float(" + v.parameter.name + ")";
}

std::string Declarations::matrix(const FixedMatrix& m) {
  if (readable(m.parameter) && components_of(m.parameter.type) == 16) {
    uniform(m.parameter.type, m.parameter.name);
    return m.parameter.name;
  }
  std::string s = "float4x4(";
  for (int i = 0; i < 16; ++i) s += (i ? ", " : "") + literal(m.value[i]);
  return s + ")";
}

}  // namespace fx::ff_detail

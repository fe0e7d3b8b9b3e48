// HLSL spelling shared by the fixed-function generators: literals, values bound to effect
// parameters (declared once with the parameter's own name and type) and the declarations
// a generated shader collects before its body.
#pragma once
#include <map>
#include <string>

#include "fx/emulation/fixed_function.h"

namespace fx::ff_detail {

// A float as an HLSL literal that reads back to the same float ("0.5", "1e-05", "-2.0").
std::string literal(float v);
// float4(a, b, c, d) of four literals.
std::string literal4(const std::array<float, 4>& v);

// The declarations of one generated shader, in the order they were first needed.
class Declarations {
 public:
  // Declares `name` of `type` once (a parameter, a fx_ff_* uniform or a sampler).
  void uniform(const std::string& type, const std::string& name);
  std::string text() const { return text_; }

  // A value as a float4 expression: a literal, or the parameter widened to four components
  // (missing components from `pad`; a scalar is splatted; an int/uint/DWORD is a D3DCOLOR).
  // An array, struct or object parameter keeps the literal value the state resolved to.
  std::string vector(const FixedVector& v, const std::array<float, 4>& pad = {0, 0, 0, 1});
  // A value as a float expression.
  std::string scalar(const FixedScalar& v);
  // A value as a float4x4 expression (a parameter of another shape keeps its literal value).
  std::string matrix(const FixedMatrix& m);

 private:
  std::map<std::string, std::string> declared_;
  std::string text_;
};

}  // namespace fx::ff_detail

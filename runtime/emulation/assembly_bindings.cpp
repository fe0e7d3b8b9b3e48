// What a pass gives a shader model 1 shader (see bind_pass_states in assembly.h): constant
// registers from VertexShaderConstant[n]/PixelShaderConstant[n] (a parameter by reference,
// or a literal), the shapes of the stages' textures and the bump-environment states.
#include <cctype>
#include <optional>

#include "fx/ascii_case.h"
#include "fx/emulation/assembly.h"
#include "hlsl_literal.h"

namespace fx::emulation {
namespace {

// A folded numeric literal: 1, -0.5, 2.0f.
std::optional<double> literal(const ast::Expr* e) {
  if (!e) return std::nullopt;
  if (e->kind == ast::ExprKind::int_literal || e->kind == ast::ExprKind::float_literal ||
      e->kind == ast::ExprKind::bool_literal)
    return e->number;
  if (e->kind == ast::ExprKind::unary && e->args.size() == 1 && (e->text == "-" || e->text == "+")) {
    auto v = literal(e->args[0]);
    if (v && e->text == "-") *v = -*v;
    return v;
  }
  return std::nullopt;
}

// Every number of `float4(a, b, c, d)`, `{a, b, c, d}` or `a`, in order; false when one is not a literal.
bool literals(const ast::Expr* e, std::vector<double>& out) {
  if (!e) return false;
  if (auto v = literal(e)) {
    out.push_back(*v);
    return true;
  }
  if (e->kind != ast::ExprKind::call && e->kind != ast::ExprKind::init_list) return false;
  for (const ast::ExprPtr& a : e->args)
    if (!literals(a, out)) return false;
  return true;
}

// "float4x3" -> rows 4, columns 3; "float3" -> 1 x 3; "float" -> 1 x 1; "matrix" -> 4 x 4.
bool shape_of(std::string type, int& rows, int& columns) {
  type = ascii_lower(type);
  if (type == "matrix") return rows = columns = 4, true;
  if (type == "vector") return rows = 1, columns = 4, true;
  for (std::string_view base : {"float", "half", "double", "int", "bool", "uint", "min16float"}) {
    if (!type.starts_with(base)) continue;
    std::string_view rest = std::string_view(type).substr(base.size());
    if (rest.empty()) return rows = columns = 1, true;
    if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return rows = 1, columns = rest[0] - '0', true;
    if (rest.size() == 3 && rest[1] == 'x' && rest[0] >= '1' && rest[0] <= '4' && rest[2] >= '1' && rest[2] <= '4')
      return rows = rest[0] - '0', columns = rest[2] - '0', true;
  }
  return false;
}

std::string pad4(const std::string& v, int n) {
  if (n == 4) return "(float4)(" + v + ")";
  std::string s = "float4(" + v;
  for (int k = n; k < 4; ++k) s += ", 0.0";
  return s + ")";
}

class Binder {
 public:
  Binder(bool pixel, std::span<const ast::Variable* const> variables, DiagnosticSink& sink)
      : pixel_(pixel), variables_(variables), sink_(sink) {}

  const ast::Variable* variable(std::string_view name) const {
    for (const ast::Variable* v : variables_)
      if (v && v->name == name) return v;
    return nullptr;
  }

  void constants(const ast::StateAssignment& s, uint32_t first) {
    const ast::Expr* value = s.value;
    if (value->kind == ast::ExprKind::reference || value->kind == ast::ExprKind::identifier) {
      parameter(*value, first);
      return;
    }
    std::vector<double> numbers;
    if (!literals(value, numbers) || numbers.empty()) {
      sink_.error("asm-constant", value->range, "a shader constant is a parameter (<name>) or numbers");
      return;
    }
    for (size_t r = 0; r * 4 < numbers.size(); ++r) {
      std::string v = "float4(";
      for (size_t k = 0; k < 4; ++k)
        v += (k ? ", " : "") + hlsl_number(r * 4 + k < numbers.size() ? numbers[r * 4 + k] : 0.0);
      out_.constants[first + uint32_t(r)] = v + ")";
    }
  }

  // A parameter spans registers as D3DX uploads it: a column-major matrix one column per
  // register (row_major: one row), an array one element (or matrix) after another.
  void parameter(const ast::Expr& value, uint32_t first) {
    const ast::Variable* v = variable(value.text);
    if (!v) {
      sink_.error("asm-constant", value.range, "no parameter named '" + std::string(value.text) + "'");
      return;
    }
    int rows = 0, columns = 0;
    if (!shape_of(std::string(v->type.name), rows, columns) || v->array_dims.size() > 1) {
      sink_.error("asm-constant", value.range,
                  std::string(1, '\'').append(v->name) + "' (" + std::string(v->type.name) +
                      ") is not a scalar, vector or matrix (or an array of them) to load into constant registers");
      return;
    }
    uint32_t count = 1;
    if (v->array_dims.size() == 1) {
      auto n = literal(v->array_dims[0]);
      if (!n || *n < 1) {
        sink_.error("asm-constant", value.range,
                    std::string(1, '\'').append(v->name) + "' needs a constant array size");
        return;
      }
      count = uint32_t(*n);
    }
    const bool row_major = (v->storage & ast::kRowMajor) != 0;
    std::string name(v->name), type(v->type.name);
    if (rows > 1 && row_major) type = "row_major " + type;
    if (rows > 1 && !row_major) type = "column_major " + type;
    std::string declaration = type + " " + name;
    if (!v->array_dims.empty()) declaration.append("[").append(std::to_string(count)).append("]");
    declaration += ";";
    bool seen = false;
    for (const std::string& d : out_.declarations) seen = seen || d == declaration;
    if (!seen) out_.declarations.push_back(declaration);
    uint32_t reg = first;
    for (uint32_t e = 0; e < count; ++e) {
      const std::string element = v->array_dims.empty() ? name : name + "[" + std::to_string(e) + "]";
      if (rows == 1) {
        out_.constants[reg++] = pad4(element, columns);
        continue;
      }
      const int registers = row_major ? rows : columns, width = row_major ? columns : rows;
      for (int k = 0; k < registers; ++k) {
        std::string part = row_major ? element + "[" + std::to_string(k) + "]"
                                     : "transpose(" + element + ")[" + std::to_string(k) + "]";
        out_.constants[reg++] = pad4(part, width);
      }
    }
  }

  void texture(const ast::StateAssignment& s, uint32_t stage) {
    if (stage >= 8 || !s.value) return;
    const ast::Variable* v = variable(s.value->text);
    if (!v) return;
    std::string type = ascii_lower(std::string(v->type.name));
    if (type == "texturecube") out_.shapes[stage] = StageShape::cube;
    else if (type == "texture3d" || type == "texturevolume") out_.shapes[stage] = StageShape::volume;
  }

  void bump(const ast::StateAssignment& s, uint32_t stage) {
    if (stage >= 8) return;
    auto v = literal(s.value);
    if (!v) return;
    std::string name = ascii_lower(std::string(s.name));
    BumpEnvironment& b = out_.bump[stage];
    if (name == "bumpenvmat00") b.matrix[0] = *v;
    else if (name == "bumpenvmat01") b.matrix[1] = *v;
    else if (name == "bumpenvmat10") b.matrix[2] = *v;
    else if (name == "bumpenvmat11") b.matrix[3] = *v;
    else if (name == "bumpenvlscale") b.scale = *v;
    else if (name == "bumpenvloffset") b.offset = *v;
  }

  void state(const ast::StateAssignment& s) {
    if (!s.value || s.call_style) return;
    std::optional<double> index = s.index ? literal(s.index) : std::optional<double>(0.0);
    const std::string name = ascii_lower(std::string(s.name));
    const std::string prefix = pixel_ ? "pixelshaderconstant" : "vertexshaderconstant";
    if (name.starts_with(prefix)) {
      std::string form = name.substr(prefix.size());
      if (form == "b" || form == "i") return;  // bool and int registers: no shader model 1 use
      if (!index || *index < 0) {
        sink_.error("asm-constant", s.range, "a shader constant state needs a constant register index");
        return;
      }
      constants(s, uint32_t(*index));
      return;
    }
    if (!index) return;
    if (name == "texture") texture(s, uint32_t(*index));
    else if (name.starts_with("bumpenv")) bump(s, uint32_t(*index));
  }

  AssemblyBindings out_;

 private:
  bool pixel_;
  std::span<const ast::Variable* const> variables_;
  DiagnosticSink& sink_;
};

}  // namespace

AssemblyBindings bind_pass_states(const ast::Pass& pass, bool pixel, std::span<const ast::Variable* const> variables,
                                  DiagnosticSink& sink) {
  Binder b(pixel, variables, sink);
  for (const ast::StateAssignment& s : pass.states) b.state(s);
  return std::move(b.out_);
}

}  // namespace fx::emulation

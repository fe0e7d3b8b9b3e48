// Constant folding of effect expressions: initializers, annotation values, state values,
// array sizes and compile-time shader arguments.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "fx/model/value.h"
#include "model_internal.h"

namespace fx {
namespace {

// HLSL's usual arithmetic conversions pick the "larger" base.
BaseType promote(BaseType a, BaseType b) {
  return static_cast<BaseType>(std::max(static_cast<int>(a), static_cast<int>(b)));
}

bool is_integer(BaseType b) { return b == BaseType::boolean || b == BaseType::int32 || b == BaseType::uint32; }

class Folder {
 public:
  Folder(const ConstantScope& scope, DiagnosticSink& diags, bool quiet) : scope_(scope), diags_(diags), quiet_(quiet) {}

  std::optional<Value> fold(const ast::Expr& e, int depth = 0) {
    if (depth > 256) return fail("not-constant", e.range, "expression nested too deeply to fold");
    switch (e.kind) {
      case ast::ExprKind::int_literal: {
        bool unsigned_suffix = !e.text.empty() && (e.text.back() == 'u' || e.text.back() == 'U');
        return make_scalar(unsigned_suffix ? BaseType::uint32 : BaseType::int32, e.number);
      }
      case ast::ExprKind::float_literal: {
        Value v;
        v.type = make_numeric(BaseType::float32);
        v.components.push_back(static_cast<float>(e.number));
        return v;
      }
      case ast::ExprKind::bool_literal: return make_scalar(BaseType::boolean, e.number);
      case ast::ExprKind::string_literal: return make_string(e.text);
      case ast::ExprKind::identifier:
      case ast::ExprKind::reference: {
        if (e.text == "true" || e.text == "TRUE") return make_scalar(BaseType::boolean, 1);
        if (e.text == "false" || e.text == "FALSE") return make_scalar(BaseType::boolean, 0);
        if (scope_.lookup)
          if (const Value* v = scope_.lookup(e.text)) return *v;
        return fail("not-constant", e.range, "'" + e.text + "' is not a constant");
      }
      case ast::ExprKind::unary: return unary(e, depth);
      case ast::ExprKind::binary: return binary(e, depth);
      case ast::ExprKind::ternary: return ternary(e, depth);
      case ast::ExprKind::call: return call(e, depth);
      case ast::ExprKind::cast: return cast(e, depth);
      case ast::ExprKind::init_list: return list(e, depth);
      case ast::ExprKind::index: return index(e, depth);
      case ast::ExprKind::member: return member(e, depth);
      default: return fail("not-constant", e.range, "not a constant expression");
    }
  }

 private:
  std::optional<Value> fail(const char* id, SourceRange r, std::string message) {
    if (!quiet_) diags_.error(id, r, std::move(message));
    return std::nullopt;
  }
  void warn(const char* id, SourceRange r, std::string message) {
    if (!quiet_) diags_.warning(id, r, std::move(message));
  }

  std::optional<Value> arg(const ast::Expr& e, size_t i, int depth) {
    if (i >= e.args.size() || !e.args[i]) return fail("not-constant", e.range, "missing operand");
    auto v = fold(*e.args[i], depth + 1);
    if (v && !v->is_numeric() && e.kind != ast::ExprKind::init_list)
      return fail("not-constant", e.args[i]->range, "a string cannot be an operand");
    return v;
  }

  std::optional<Value> unary(const ast::Expr& e, int depth) {
    auto v = arg(e, 0, depth);
    if (!v) return v;
    for (double& c : v->components) {
      if (e.text == "-") c = -c;
      else if (e.text == "+") {
      } else if (e.text == "!") c = c == 0 ? 1 : 0;
      else if (e.text == "~") c = static_cast<double>(~static_cast<uint32_t>(static_cast<int64_t>(c)));
      else return fail("not-constant", e.range, "operator '" + e.text + "' is not constant");
    }
    if (e.text == "!") v->type.base = BaseType::boolean;
    if (e.text == "~") {
      if (!is_integer(v->type.base)) return fail("not-constant", e.range, "'~' needs an integer operand");
      if (v->type.base == BaseType::int32)
        for (double& c : v->components) c = convert_component(c, BaseType::int32);
    }
    if (e.text == "-" && v->type.base == BaseType::uint32)
      for (double& c : v->components) c = convert_component(c, BaseType::uint32);
    return v;
  }

  // Shapes of two operands combined: scalars broadcast; otherwise the smaller count wins
  // (HLSL truncates the larger operand with a warning).
  bool combine_shape(const Value& a, const Value& b, Type& out, SourceRange r) {
    size_t na = a.components.size(), nb = b.components.size();
    if (na == 1) out = b.type;
    else if (nb == 1 || na == nb) out = a.type;
    else {
      warn("truncated-initializer", r, "operands of different sizes: the larger is truncated");
      out = na < nb ? a.type : b.type;
    }
    out.base = promote(a.type.base, b.type.base);
    return true;
  }

  std::optional<Value> binary(const ast::Expr& e, int depth) {
    const std::string& op = e.text;
    if (op == ",") {
      auto rhs = arg(e, 1, depth);
      return rhs;
    }
    auto a = arg(e, 0, depth);
    if (!a) return a;
    auto b = arg(e, 1, depth);
    if (!b) return b;
    Value out;
    combine_shape(*a, *b, out.type, e.range);
    size_t n = out.type.component_count();
    BaseType base = out.type.base;
    bool compare = op == "<" || op == ">" || op == "<=" || op == ">=" || op == "==" || op == "!=";
    bool logic = op == "&&" || op == "||";
    bool bits = op == "&" || op == "|" || op == "^" || op == "<<" || op == ">>" || op == "%";
    if (bits && op != "%" && (!is_integer(a->type.base) || !is_integer(b->type.base)))
      return fail("not-constant", e.range, "'" + op + "' needs integer operands");
    for (size_t i = 0; i < n; ++i) {
      double x = a->components.size() == 1 ? a->components[0] : a->components[i];
      double y = b->components.size() == 1 ? b->components[0] : b->components[i];
      double r = 0;
      if (op == "+") r = x + y;
      else if (op == "-") r = x - y;
      else if (op == "*") r = x * y;
      else if (op == "/" || op == "%") {
        if (y == 0) {
          if (is_integer(base)) return fail("division-by-zero", e.range, "integer division by zero in a constant");
          warn("division-by-zero", e.range, "floating-point division by zero in a constant");
        }
        if (op == "/") r = is_integer(base) ? std::trunc(x / y) : x / y;
        else r = is_integer(base) ? std::fmod(std::trunc(x), std::trunc(y)) : std::fmod(x, y);
      } else if (op == "<") r = x < y;
      else if (op == ">") r = x > y;
      else if (op == "<=") r = x <= y;
      else if (op == ">=") r = x >= y;
      else if (op == "==") r = x == y;
      else if (op == "!=") r = x != y;
      else if (op == "&&") r = x != 0 && y != 0;
      else if (op == "||") r = x != 0 || y != 0;
      else if (op == "&" || op == "|" || op == "^" || op == "<<" || op == ">>") {
        uint32_t u = static_cast<uint32_t>(static_cast<int64_t>(x)), v = static_cast<uint32_t>(static_cast<int64_t>(y));
        uint32_t s = v & 31;
        uint32_t res = op == "&"                 ? u & v
                       : op == "|"               ? u | v
                       : op == "^"               ? u ^ v
                       : op == "<<"              ? u << s
                       : base == BaseType::int32 ? static_cast<uint32_t>(static_cast<int32_t>(u) >> s)
                                                 : u >> s;
        r = res;
      } else {
        return fail("not-constant", e.range, "operator '" + op + "' is not constant");
      }
      out.components.push_back(r);
    }
    if (compare || logic) out.type.base = BaseType::boolean;
    for (double& c : out.components) c = convert_component(c, out.type.base);
    return out;
  }

  std::optional<Value> ternary(const ast::Expr& e, int depth) {
    auto c = arg(e, 0, depth);
    if (!c) return c;
    if (c->components.size() == 1) return fold_branch(e, c->components[0] != 0 ? 1 : 2, depth);
    auto a = arg(e, 1, depth);
    if (!a) return a;
    auto b = arg(e, 2, depth);
    if (!b) return b;
    Value out;
    combine_shape(*a, *b, out.type, e.range);
    for (size_t i = 0; i < out.type.component_count(); ++i) {
      double cond = i < c->components.size() ? c->components[i] : 0;
      const Value& pick = cond != 0 ? *a : *b;
      out.components.push_back(
          convert_component(pick.components.size() == 1 ? pick.components[0] : pick.components[i], out.type.base));
    }
    return out;
  }
  std::optional<Value> fold_branch(const ast::Expr& e, size_t i, int depth) {
    if (i >= e.args.size() || !e.args[i]) return fail("not-constant", e.range, "missing operand");
    return fold(*e.args[i], depth + 1);
  }

  Type type_named(std::string_view name) const {
    if (scope_.types) return scope_.types->lookup(name);
    TypeTable none;
    return none.lookup(name);
  }

  // Every argument's components, flattened (constructors and lists).
  std::optional<Value> flatten_args(const ast::Expr& e, int depth, BaseType& base) {
    Value flat;
    bool first = true;
    for (size_t i = 0; i < e.args.size(); ++i) {
      auto v = arg(e, i, depth);
      if (!v) return v;
      if (v->is_string()) return fail("not-constant", e.args[i]->range, "a string cannot be a component");
      base = first ? v->type.base : promote(base, v->type.base);
      first = false;
      flat.components.insert(flat.components.end(), v->components.begin(), v->components.end());
    }
    return flat;
  }

  std::optional<Value> call(const ast::Expr& e, int depth) {
    Type t = type_named(e.text);
    if (t.is_numeric() || (t.cls == TypeClass::structure && t.structure)) {
      BaseType base = BaseType::float32;
      auto flat = flatten_args(e, depth, base);
      if (!flat) return flat;
      size_t want = t.component_count(), have = flat->components.size();
      if (have == 1 && t.is_numeric()) flat->components.assign(want, flat->components[0]);
      else if (have != want)
        return fail(
            "bad-constructor", e.range,
            t.to_string() + " constructor needs " + std::to_string(want) + " components, got " + std::to_string(have));
      flat->type = t;
      for (double& c : flat->components) c = convert_component(c, t.base);
      return flat;
    }
    return intrinsic(e, depth);
  }

  std::optional<Value> intrinsic(const ast::Expr& e, int depth) {
    const std::string& f = e.text;
    static const char* unary_names[] = {"abs", "sqrt", "sin", "cos",  "tan",     "floor",   "ceil",  "frac", "saturate",
                                        "exp", "exp2", "log", "log2", "radians", "degrees", "rsqrt", "round"};
    bool is_unary = std::any_of(std::begin(unary_names), std::end(unary_names), [&](const char* n) { return f == n; });
    if (is_unary && e.args.size() == 1) {
      auto v = arg(e, 0, depth);
      if (!v) return v;
      if (is_integer(v->type.base) && f != "abs") v->type.base = BaseType::float32;
      for (double& c : v->components) {
        if (f == "abs") c = std::fabs(c);
        else if (f == "sqrt") c = std::sqrt(c);
        else if (f == "rsqrt") c = 1.0 / std::sqrt(c);
        else if (f == "sin") c = std::sin(c);
        else if (f == "cos") c = std::cos(c);
        else if (f == "tan") c = std::tan(c);
        else if (f == "floor") c = std::floor(c);
        else if (f == "ceil") c = std::ceil(c);
        else if (f == "round") c = std::nearbyint(c);
        else if (f == "frac") c = c - std::floor(c);
        else if (f == "saturate") c = std::clamp(c, 0.0, 1.0);
        else if (f == "exp") c = std::exp(c);
        else if (f == "exp2") c = std::exp2(c);
        else if (f == "log") c = std::log(c);
        else if (f == "log2") c = std::log2(c);
        else if (f == "radians") c = c * 3.14159265358979323846 / 180.0;
        else if (f == "degrees") c = c * 180.0 / 3.14159265358979323846;
        c = convert_component(c, v->type.base);
      }
      return v;
    }
    if ((f == "min" || f == "max" || f == "pow" || f == "dot") && e.args.size() == 2) {
      auto a = arg(e, 0, depth);
      if (!a) return a;
      auto b = arg(e, 1, depth);
      if (!b) return b;
      Value out;
      combine_shape(*a, *b, out.type, e.range);
      double sum = 0;
      for (size_t i = 0; i < out.type.component_count(); ++i) {
        double x = a->components.size() == 1 ? a->components[0] : a->components[i];
        double y = b->components.size() == 1 ? b->components[0] : b->components[i];
        double r = f == "min" ? std::min(x, y) : f == "max" ? std::max(x, y) : f == "pow" ? std::pow(x, y) : x * y;
        sum += r;
        out.components.push_back(r);
      }
      if (f == "dot") {
        out.type = make_numeric(out.type.base);
        out.components = {sum};
      }
      return out;
    }
    if ((f == "lerp" || f == "clamp") && e.args.size() == 3) {
      auto a = arg(e, 0, depth), b = a ? arg(e, 1, depth) : a, c = b ? arg(e, 2, depth) : b;
      if (!c) return c;
      Value out;
      combine_shape(*a, *b, out.type, e.range);
      for (size_t i = 0; i < out.type.component_count(); ++i) {
        auto at = [i](const Value& v) {
          return v.components.size() == 1 ? v.components[0] : v.components[std::min(i, v.components.size() - 1)];
        };
        double x = at(*a), y = at(*b), z = at(*c);
        out.components.push_back(f == "lerp" ? x + (y - x) * z : std::clamp(x, std::min(y, z), std::max(y, z)));
      }
      return out;
    }
    return fail("not-constant", e.range, "'" + f + "(...)' is not a constant expression");
  }

  std::optional<Value> cast(const ast::Expr& e, int depth) {
    auto v = arg(e, 0, depth);
    if (!v) return v;
    Type t = type_named(e.text);
    if (!t.is_numeric()) return fail("not-constant", e.range, "cannot fold a cast to '" + e.text + "'");
    size_t want = t.component_count();
    if (v->components.size() == 1) v->components.assign(want, v->components[0]);
    else if (v->components.size() > want) v->components.resize(want);
    else if (v->components.size() < want) return fail("bad-constructor", e.range, "cast to a larger type");
    v->type = t;
    for (double& c : v->components) c = convert_component(c, t.base);
    return v;
  }

  std::optional<Value> list(const ast::Expr& e, int depth) {
    if (e.args.size() == 1 && e.args[0] && e.args[0]->kind == ast::ExprKind::string_literal)
      return fold(*e.args[0], depth + 1);
    BaseType base = BaseType::int32;
    auto flat = flatten_args(e, depth, base);
    if (!flat) return flat;
    flat->type = make_numeric(base);
    flat->type.array_dims = {static_cast<uint32_t>(flat->components.size())};
    if (flat->components.empty()) return fail("not-constant", e.range, "empty initializer list");
    return flat;
  }

  std::optional<Value> index(const ast::Expr& e, int depth) {
    auto v = arg(e, 0, depth);
    if (!v) return v;
    auto i = arg(e, 1, depth);
    if (!i) return i;
    double k = i->number();
    Type elem;
    if (v->type.is_array()) elem = v->type.element_type();
    else if (v->type.cls == TypeClass::matrix) elem = make_numeric(v->type.base, 1, v->type.cols);
    else if (v->type.cls == TypeClass::vector) elem = make_numeric(v->type.base);
    else return fail("not-constant", e.range, "cannot index a " + v->type.to_string());
    size_t stride = elem.component_count();
    size_t count = stride ? v->components.size() / stride : 0;
    if (k < 0 || k >= static_cast<double>(count))
      return fail("index-out-of-range", e.args[1]->range,
                  "index " + i->to_string() + " out of range for " + v->type.to_string());
    Value out;
    out.type = elem;
    auto first = v->components.begin() + static_cast<long>(static_cast<size_t>(k) * stride);
    out.components.assign(first, first + static_cast<long>(stride));
    return out;
  }

  std::optional<Value> member(const ast::Expr& e, int depth) {
    auto v = arg(e, 0, depth);
    if (!v) return v;
    if (v->type.cls == TypeClass::structure && v->type.structure && !v->type.is_array()) {
      const StructMember* m = v->type.structure->find(e.text);
      if (!m) return fail("not-constant", e.range, "no member '" + e.text + "'");
      Value out;
      out.type = m->type;
      auto first = v->components.begin() + m->component_offset;
      out.components.assign(first, first + m->type.component_count());
      return out;
    }
    if (!v->type.is_numeric() || v->type.is_array() || v->type.cls == TypeClass::matrix)
      return fail("bad-swizzle", e.range, "cannot swizzle a " + v->type.to_string());
    const std::string& s = e.text;
    if (s.empty() || s.size() > 4) return fail("bad-swizzle", e.range, "bad swizzle '." + s + "'");
    bool xyzw = s.find_first_of("xyzw") != std::string::npos, rgba = s.find_first_of("rgba") != std::string::npos;
    if (xyzw && rgba) return fail("bad-swizzle", e.range, "swizzle '." + s + "' mixes xyzw and rgba");
    Value out;
    for (char c : s) {
      const char* set = rgba ? "rgba" : "xyzw";
      const char* p = std::strchr(set, c);
      size_t k = p ? static_cast<size_t>(p - set) : 99;
      if (!p || c == 0 || k >= v->components.size())
        return fail("bad-swizzle", e.range, "swizzle '." + s + "' reads past a " + v->type.to_string());
      out.components.push_back(v->components[k]);
    }
    out.type = make_numeric(v->type.base, 1, static_cast<uint8_t>(s.size()));
    return out;
  }

  const ConstantScope& scope_;
  DiagnosticSink& diags_;
  bool quiet_;
};

}  // namespace

std::optional<Value> fold_constant(const ast::Expr& expr, const ConstantScope& scope, DiagnosticSink& diags,
                                   bool quiet) {
  Folder folder(scope, diags, quiet);
  return folder.fold(expr);
}

}  // namespace fx

// ParameterStore: a flat node array (parameters, struct members, array elements) over
// 32-bit words, one per scalar component (float bits, int, uint, bool 0/1). Matrices are
// stored in D3D order (m[r][c] at r*cols+c); each bound block keeps a packed copy that a
// set updates (parameter_block.cpp).
#include <algorithm>
#include <cstring>
#include <utility>

#include "parameter_store_impl.h"

namespace fx {

ParameterStore::ParameterStore(const EffectModel& model, ParameterPool* pool, DiagnosticSink* diags)
    : impl_(std::make_unique<Impl>()), draw_(&impl_->draw) {
  Impl& s = *impl_;
  s.model = &model;
  s.pool = pool;
  s.top_count = static_cast<uint32_t>(model.parameters.size());
  s.nodes.resize(s.top_count);
  s.draw.versions.assign(s.top_count, 1);
  s.draw.hot.assign(s.top_count, {});
  for (uint32_t i = 0; i < s.top_count; ++i) {
    const Parameter& p = model.parameters[i];
    Impl::Node& n = s.nodes[i];
    n.type = p.type;
    n.top = i;
    n.words = p.type.is_numeric() || p.type.cls == TypeClass::structure ? p.type.component_count() : 0;
    if (p.type.cls == TypeClass::string) {
      n.string_slot = static_cast<uint32_t>(s.strings.size());
      s.strings.push_back(p.default_value && p.default_value->is_string() ? p.default_value->text : "");
    }
    bool shared = pool && p.is_shared() && n.words > 0;
    if (shared) {
      auto it = pool->by_name_.find(p.name);
      if (it != pool->by_name_.end() && !pool->entries_[it->second].type.same_as(p.type)) {
        if (diags)
          diags->error("shared-type-mismatch", p.name_range,
                       "shared parameter '" + p.name + "' is a " + p.type.to_string() + " here but a " +
                           pool->entries_[it->second].type.to_string() + " in the pool; it gets its own storage");
        shared = false;
      } else if (it == pool->by_name_.end()) {
        ParameterPool::Entry e{p.name, p.type, static_cast<uint32_t>(pool->words_.size()), n.words, 1};
        std::vector<BaseType> b;
        flatten_bases(p.type, b);
        for (uint32_t w = 0; w < n.words; ++w)
          pool->words_.push_back(p.default_value && w < p.default_value->components.size()
                                     ? encode(p.default_value->components[w], b[w])
                                     : 0);
        pool->by_name_.emplace(p.name, static_cast<uint32_t>(pool->entries_.size()));
        pool->entries_.push_back(std::move(e));
        it = pool->by_name_.find(p.name);
      }
      if (shared) {
        n.pooled = true;
        n.pool_entry = it->second;
        n.offset = pool->entries_[it->second].offset;
      }
    }
    n.base_offset = static_cast<uint32_t>(s.bases.size());
    if (n.words) {
      std::vector<BaseType> b;
      flatten_bases(p.type, b);
      s.bases.insert(s.bases.end(), b.begin(), b.end());
    }
    if (!n.pooled) {
      n.offset = static_cast<uint32_t>(s.words.size());
      for (uint32_t w = 0; w < n.words; ++w) {
        BaseType b = s.bases[n.base_offset + w];
        s.words.push_back(
            p.default_value && w < p.default_value->components.size() ? encode(p.default_value->components[w], b) : 0);
      }
    }
    s.by_name.emplace(p.name, i);
    if (!p.semantic.empty()) s.by_semantic.emplace(ascii_lower(p.semantic), i);
  }
  for (uint32_t i = 0; i < s.top_count; ++i) {
    s.classify(s.nodes[i]);
    if (s.nodes[i].words) s.expand(i);
  }
  s.set_by_app.assign(s.words.size(), 0);
  s.string_set_by_app.assign(s.strings.size(), 0);
}

ParameterStore::ParameterStore(ParameterStore&& other) noexcept
    : impl_(std::move(other.impl_)), draw_(std::exchange(other.draw_, nullptr)) {}
ParameterStore& ParameterStore::operator=(ParameterStore&& other) noexcept {
  impl_ = std::move(other.impl_);
  draw_ = std::exchange(other.draw_, nullptr);
  return *this;
}
ParameterStore::~ParameterStore() = default;

Param ParameterStore::find(std::string_view name) const {
  auto it = impl_->by_name.find(std::string(name));
  return it == impl_->by_name.end() ? Param{} : Param{it->second, impl_->draw.generation};
}

Param ParameterStore::by_semantic(std::string_view semantic) const {
  auto it = impl_->by_semantic.find(ascii_lower(semantic));
  return it == impl_->by_semantic.end() ? Param{} : Param{it->second, impl_->draw.generation};
}

Param ParameterStore::member(Param p, std::string_view name) const {
  uint32_t i;
  if (!impl_->resolve(p, i)) return {};
  const Impl::Node& n = impl_->nodes[i];
  if (n.type.is_array() || n.type.cls != TypeClass::structure) return {};
  for (uint32_t k = 0; k < n.child_count; ++k)
    if (impl_->nodes[n.first_child + k].member == name) return {n.first_child + k, impl_->draw.generation};
  return {};
}

Param ParameterStore::element(Param p, uint32_t e) const {
  uint32_t i;
  if (!impl_->resolve(p, i)) return {};
  const Impl::Node& n = impl_->nodes[i];
  if (!n.type.is_array() || e >= n.child_count) return {};
  return {n.first_child + e, impl_->draw.generation};
}

Param ParameterStore::current(Param p) const {
  uint32_t i;
  return impl_->resolve(p, i) ? Param{i, impl_->draw.generation} : Param{};
}

const Type* ParameterStore::type(Param p) const {
  uint32_t i;
  return impl_->resolve(p, i) ? &impl_->nodes[i].type : nullptr;
}

std::string ParameterStore::name(Param p) const {
  uint32_t i;
  return impl_->resolve(p, i) ? impl_->path(i) : std::string();
}

size_t ParameterStore::parameter_count() const { return impl_->top_count; }
uint32_t ParameterStore::generation() const { return impl_->draw.generation; }

ParamStatus ParameterStore::set(Param p, float v) { return set(p, std::span<const float>(&v, 1)); }

ParamStatus ParameterStore::set(Param p, int32_t v) { return set(p, std::span<const int32_t>(&v, 1)); }

ParamStatus ParameterStore::set(Param p, bool v) {
  int32_t i = v ? 1 : 0;
  return set(p, std::span<const int32_t>(&i, 1));
}

ParamStatus ParameterStore::Impl::write_floats(uint32_t i, const float* v, size_t count) {
  const Node& n = nodes[i];
  if (!uniform_kind(n, true)) return fail(ParamStatus::type_mismatch, "cannot set " + describe(i) + " from floats");
  if (count != n.words)
    return fail(ParamStatus::size_mismatch,
                describe(i) + " takes " + std::to_string(n.words) + " floats, got " + std::to_string(count));
  store_floats(n, v);
  return {};
}

ParamStatus ParameterStore::set(Param p, std::span<const float> v) {
  uint32_t i;
  if (ParamStatus st = impl_->resolve(p, i); !st) return st;
  return impl_->write_floats(i, v.data(), v.size());
}

ParamStatus ParameterStore::set(Param p, std::span<const int32_t> v) {
  Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  if (!s.uniform_kind(n, false))
    return fail(ParamStatus::type_mismatch, "cannot set " + s.describe(i) + " from integers");
  if (v.size() != n.words)
    return fail(ParamStatus::size_mismatch,
                s.describe(i) + " takes " + std::to_string(n.words) + " integers, got " + std::to_string(v.size()));
  s.mark_set(n, true);
  uint32_t* d = s.data(n);
  bool changed = false;
  for (uint32_t w = 0; w < n.words; ++w) {
    const uint32_t word = encode(v[w], s.base_at(n, w));
    changed = changed || d[w] != word;
    d[w] = word;
  }
  if (changed) s.touch(n);
  return {};
}

bool ParameterStore::set_matrix_fast(Param p, const float* v, size_t count, fxkit::MatrixOrder order) {
  Impl& s = *impl_;
  if (p.generation != s.draw.generation || p.index >= s.nodes.size()) return false;
  const Impl::Node& n = s.nodes[p.index];
  if (n.type.cls != TypeClass::matrix || !n.all_float || count != n.words) return false;
  s.sync(n.top);
  if (order == fxkit::MatrixOrder::row_major) {
    s.store_floats(n, v);
    return true;
  }
  if (count != 16 || n.type.rows != 4 || n.type.cols != 4) return false;  // arrays, other shapes: the checked path
  s.store_columns4x4(n, v);
  return true;
}

ParamStatus ParameterStore::set_matrix_checked(Param p, std::span<const float> v, fxkit::MatrixOrder order) {
  Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  if (n.type.cls != TypeClass::matrix) return fail(ParamStatus::type_mismatch, s.describe(i) + " is not a matrix");
  if (order == fxkit::MatrixOrder::row_major) return s.write_floats(i, v.data(), v.size());
  const uint32_t r = n.type.rows, c = n.type.cols, per = r * c;
  if (v.size() != n.words)
    return fail(ParamStatus::size_mismatch,
                s.describe(i) + " takes " + std::to_string(n.words) + " floats, got " + std::to_string(v.size()));
  std::vector<float> rows(v.size());
  for (uint32_t e = 0; e < n.words / per; ++e)
    for (uint32_t a = 0; a < r; ++a)
      for (uint32_t b = 0; b < c; ++b) rows[e * per + a * c + b] = v[e * per + b * r + a];
  return s.write_floats(i, rows.data(), rows.size());
}

ParamStatus ParameterStore::set_string(Param p, std::string_view v) {
  Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  if (s.nodes[i].string_slot == kNoIndex) return fail(ParamStatus::type_mismatch, s.describe(i) + " is not a string");
  s.strings[s.nodes[i].string_slot] = std::string(v);
  s.string_set_by_app[s.nodes[i].string_slot] = 1;
  return {};
}

ParamStatus ParameterStore::get(Param p, float& out) const { return get(p, std::span<float>(&out, 1)); }
ParamStatus ParameterStore::get(Param p, int32_t& out) const { return get(p, std::span<int32_t>(&out, 1)); }

ParamStatus ParameterStore::get(Param p, bool& out) const {
  int32_t i = 0;
  ParamStatus st = get(p, std::span<int32_t>(&i, 1));
  if (st) out = i != 0;
  return st;
}

ParamStatus ParameterStore::get(Param p, std::span<float> out) const {
  const Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  if (!s.uniform_kind(n, true)) return fail(ParamStatus::type_mismatch, "cannot read " + s.describe(i) + " as floats");
  if (out.size() != n.words)
    return fail(ParamStatus::size_mismatch, s.describe(i) + " has " + std::to_string(n.words) + " floats, the output " +
                                                std::to_string(out.size()));
  const uint32_t* d = s.data(n);
  for (uint32_t w = 0; w < n.words; ++w) out[w] = bits_float(d[w]);
  return {};
}

ParamStatus ParameterStore::get(Param p, std::span<int32_t> out) const {
  const Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  if (!s.uniform_kind(n, false))
    return fail(ParamStatus::type_mismatch, "cannot read " + s.describe(i) + " as integers");
  if (out.size() != n.words)
    return fail(ParamStatus::size_mismatch, s.describe(i) + " has " + std::to_string(n.words) +
                                                " integers, the output " + std::to_string(out.size()));
  const uint32_t* d = s.data(n);
  for (uint32_t w = 0; w < n.words; ++w) out[w] = static_cast<int32_t>(d[w]);
  return {};
}

ParamStatus ParameterStore::get_matrix(Param p, std::span<float> out, fxkit::MatrixOrder order) const {
  const Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  if (n.type.cls != TypeClass::matrix) return fail(ParamStatus::type_mismatch, s.describe(i) + " is not a matrix");
  if (ParamStatus st = get(p, out); !st || order == fxkit::MatrixOrder::row_major) return st;
  const uint32_t r = n.type.rows, c = n.type.cols, per = r * c;
  std::vector<float> rows(out.begin(), out.end());
  for (uint32_t e = 0; e < n.words / per; ++e)
    for (uint32_t a = 0; a < r; ++a)
      for (uint32_t b = 0; b < c; ++b) out[e * per + b * r + a] = rows[e * per + a * c + b];
  return {};
}

ParamStatus ParameterStore::get_string(Param p, std::string& out) const {
  const Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  if (s.nodes[i].string_slot == kNoIndex) return fail(ParamStatus::type_mismatch, s.describe(i) + " is not a string");
  out = s.strings[s.nodes[i].string_slot];
  return {};
}

ParamStatus ParameterStore::reset(Param p) {
  Impl& s = *impl_;
  uint32_t i;
  if (ParamStatus st = s.resolve(p, i); !st) return st;
  const Impl::Node& n = s.nodes[i];
  const Parameter& top = s.model->parameters[n.top];
  if (n.string_slot != kNoIndex) {
    s.strings[n.string_slot] = top.default_value ? top.default_value->text : "";
    s.string_set_by_app[n.string_slot] = 0;
    return {};
  }
  // The default again, and followed from now on: a hot matrix is made only for a matrix the
  // application sets (Impl::refresh), so this one stops being hot until it is set again.
  s.mark_set(n, false);
  s.draw.hot[n.top] = {};
  const uint32_t top_offset = s.nodes[n.top].offset;
  std::vector<BaseType> b;
  flatten_bases(top.type, b);
  uint32_t* d = s.data(n);
  for (uint32_t w = 0; w < n.words; ++w) {
    uint32_t k = n.offset - top_offset + w;
    d[w] = top.default_value && k < top.default_value->components.size()
               ? encode(top.default_value->components[k], b[k])
               : 0;
  }
  s.touch(n);
  return {};
}

}  // namespace fx

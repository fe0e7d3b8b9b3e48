#include "glslang_reflect.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include <glslang/Include/Types.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include "effect_shader_text.h"
#include "fx/compile/program_link.h"  // offset_semantic
#include "spirv_words.h"

namespace fx {
namespace {

ScalarKind scalar_kind(glslang::TBasicType t) {
  switch (t) {
    case glslang::EbtFloat: return ScalarKind::float32;
    case glslang::EbtFloat16: return ScalarKind::float16;
    case glslang::EbtDouble: return ScalarKind::float64;
    case glslang::EbtInt: return ScalarKind::int32;
    case glslang::EbtUint: return ScalarKind::uint32;
    case glslang::EbtBool: return ScalarKind::boolean;
    default: return ScalarKind::other;
  }
}

ReflectedType reflected_type(const glslang::TType& t) {
  ReflectedType r;
  r.scalar = scalar_kind(t.getBasicType());
  r.is_struct = t.isStruct();
  if (t.isMatrix()) {
    r.columns = static_cast<uint8_t>(t.getMatrixCols());
    r.rows = static_cast<uint8_t>(t.getMatrixRows());
  } else {
    r.columns = static_cast<uint8_t>(std::max(1, t.getVectorSize()));
  }
  if (t.isArray() && t.isSizedArray()) r.array_size = static_cast<uint32_t>(t.getOuterArraySize());
  glslang::TType element(t, 0);  // the element type for arrays, a copy otherwise
  if (!t.isArray()) element.shallowCopy(t);
  std::string name = element.getCompleteString(true, false, false, true).c_str();
  size_t first = name.find_first_not_of(' ');
  r.glsl_name = first == std::string::npos ? std::string() : name.substr(first);
  return r;
}

uint32_t location_of(const glslang::TType& t) {
  return t.getQualifier().hasLocation() ? t.getQualifier().layoutLocation : 0;
}

uint32_t set_of(const glslang::TType& t) { return t.getQualifier().hasSet() ? t.getQualifier().layoutSet : 0; }
uint32_t binding_of(const glslang::TType& t) {
  return t.getQualifier().hasBinding() ? t.getQualifier().layoutBinding : 0;
}

ImageDim image_dim(glslang::TSamplerDim d) {
  switch (d) {
    case glslang::Esd1D: return ImageDim::dim_1d;
    case glslang::Esd2D: return ImageDim::dim_2d;
    case glslang::Esd3D: return ImageDim::dim_3d;
    case glslang::EsdCube: return ImageDim::cube;
    case glslang::EsdBuffer: return ImageDim::buffer;
    default: return ImageDim::other;
  }
}

UniformBlock make_block(const glslang::TObjectReflection& b) {
  UniformBlock block;
  block.name = detail::effect_name(b.name);
  block.size = static_cast<uint32_t>(std::max(0, b.size));
  if (const glslang::TType* t = b.getType()) {
    block.set = set_of(*t);
    block.binding = binding_of(*t);
  }
  return block;
}

BlockMember make_member(const glslang::TObjectReflection& u, const UniformBlock& block,
                        const glslang::TType* block_type) {
  BlockMember m;
  m.name = detail::effect_name(u.name);
  m.offset = static_cast<uint32_t>(std::max(0, u.offset));
  m.array_stride = static_cast<uint32_t>(std::max(0, u.arrayStride));
  const glslang::TType* t = u.getType();
  if (!t) return m;
  m.type = reflected_type(*t);
  glslang::TLayoutMatrix layout = t->getQualifier().layoutMatrix;
  if (layout == glslang::ElmNone && block_type) layout = block_type->getQualifier().layoutMatrix;
  glslang::TLayoutPacking packing = block_type ? block_type->getQualifier().layoutPacking : glslang::ElpStd140;
  if (packing == glslang::ElpNone) packing = glslang::ElpStd140;
  int size = 0, stride = 0;
  glslang::TType element(*t, 0);
  if (!t->isArray()) element.shallowCopy(*t);
  bool row_major = layout == glslang::ElmRowMajor;
  glslang::TIntermediate::getBaseAlignment(element, size, stride, packing, row_major);
  if (t->isMatrix()) {
    m.matrix_layout = row_major ? MatrixLayout::row_major : MatrixLayout::column_major;
    m.matrix_stride = static_cast<uint32_t>(stride);
    // glslang's reflection gives an array of row-major matrices the column-major stride (64
    // for HLSL's float4x3, whose SPIR-V ArrayStride is 48): in std140 the stride is the
    // element's size rounded up to 16 bytes.
  }
  // The same for an array inside a struct (glslang gives `float scale[2]` of a struct in a
  // cbuffer a stride of 4; SPIR-V says 16): in std140 every array element starts a register.
  if (t->isArray() && packing == glslang::ElpStd140) m.array_stride = (static_cast<uint32_t>(size) + 15u) & ~15u;
  uint32_t count = m.type.array_size ? m.type.array_size : 1;
  // The last element of an array takes its own size, not a full stride (std140 and HLSL).
  m.size = m.array_stride ? m.array_stride * (count - 1) + static_cast<uint32_t>(size) : static_cast<uint32_t>(size);
  (void)block;
  return m;
}

// D3D numbers the elements of an array varying on from its semantic's index (float3 n[6] :
// NORMALS -> NORMALS0 ... NORMALS5, TEXCOORD2 -> TEXCOORD2 ... TEXCOORD7); glslang flattens
// the array into one variable per element, in location order, each with the array's
// semantic. Without the numbering, linking by semantic sent every element to one location.
void number_array_elements(std::vector<InterfaceVariable>& vars) {
  std::map<std::string, uint32_t> count, seen;
  for (const InterfaceVariable& v : vars)
    if (!v.semantic.empty()) ++count[v.semantic];
  for (InterfaceVariable& v : vars) {
    if (v.semantic.empty() || count[v.semantic] < 2) continue;
    const uint32_t element = seen[v.semantic]++;
    v.semantic = offset_semantic(v.semantic, element);
  }
}

}  // namespace

ShaderReflection reflect_program(const glslang::TProgram& program, EShLanguage stage,
                                 const std::vector<uint32_t>& spirv) {
  ShaderReflection r;
  auto& p = const_cast<glslang::TProgram&>(program);  // the getters are not const in glslang 12

  std::vector<const glslang::TType*> block_types;
  for (int i = 0; i < p.getNumUniformBlocks(); ++i) {
    const glslang::TObjectReflection& b = p.getUniformBlock(i);
    const glslang::TType* t = b.getType();
    block_types.push_back(t);
    UniformBlock block = make_block(b);
    if (t && t->getQualifier().isPushConstant()) r.push_constants.push_back(std::move(block));
    else r.uniform_blocks.push_back(std::move(block));
  }
  // Members: reflection lists them as uniforms whose index is the block's index.
  for (int i = 0; i < p.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = p.getUniform(i);
    const glslang::TType* t = u.getType();
    if (u.index >= 0 && u.index < p.getNumUniformBlocks()) {
      const glslang::TObjectReflection& b = p.getUniformBlock(u.index);
      auto& list = (b.getType() && b.getType()->getQualifier().isPushConstant()) ? r.push_constants : r.uniform_blocks;
      for (UniformBlock& block : list)
        if (block.name == b.name) block.members.push_back(make_member(u, block, block_types[u.index]));
      continue;
    }
    if (!t || t->getBasicType() != glslang::EbtSampler) continue;
    const glslang::TSampler& s = t->getSampler();
    ImageBinding img;
    img.name = detail::effect_name(u.name);
    img.kind = s.isPureSampler() ? ImageBinding::Kind::sampler
               : s.isImage()     ? ImageBinding::Kind::storage_image
               : s.isCombined()  ? ImageBinding::Kind::combined_image_sampler
                                 : ImageBinding::Kind::sampled_image;
    img.dim = image_dim(s.dim);
    img.arrayed = s.isArrayed();
    img.shadow = s.isShadow();
    img.multisampled = s.isMultiSample();
    img.sampled = s.type == glslang::EbtInt    ? ScalarKind::int32
                  : s.type == glslang::EbtUint ? ScalarKind::uint32
                                               : ScalarKind::float32;
    img.set = set_of(*t);
    img.binding = binding_of(*t);
    if (t->isArray() && t->isSizedArray()) img.array_size = static_cast<uint32_t>(t->getOuterArraySize());
    r.images.push_back(std::move(img));
  }
  // Comparison through a helper function's parameters: the code compares, the type does not say so.
  const std::set<spirv::SetBinding> compared = spirv::depth_compared_bindings(spirv);
  for (ImageBinding& img : r.images)
    if (compared.count({img.set, img.binding})) img.shadow = true;
  for (int i = 0; i < p.getNumBufferBlocks(); ++i) {
    UniformBlock block = make_block(p.getBufferBlock(i));
    const glslang::TType* t = p.getBufferBlock(i).getType();
    block.written = t && !t->getQualifier().readonly;
    r.storage_blocks.push_back(std::move(block));
  }
  for (int i = 0; i < p.getNumBufferVariables(); ++i) {
    const glslang::TObjectReflection& u = p.getBufferVariable(i);
    if (u.index < 0 || u.index >= p.getNumBufferBlocks()) continue;
    const glslang::TObjectReflection& b = p.getBufferBlock(u.index);
    for (UniformBlock& block : r.storage_blocks)
      if (block.name == b.name) block.members.push_back(make_member(u, block, b.getType()));
  }
  // glslang lists each member of a runtime array's element twice ("Particles.@data[0].pos"
  // and "Particles.@data.pos"): the element's layout is the indexed spelling's.
  for (UniformBlock& block : r.storage_blocks) {
    std::set<std::string> twice;
    for (const BlockMember& m : block.members)
      if (size_t at = m.name.find("[0]"); at != std::string::npos)
        twice.insert(m.name.substr(0, at) + m.name.substr(at + 3));
    std::erase_if(block.members, [&](const BlockMember& m) { return twice.count(m.name) > 0; });
  }
  for (auto* list : {&r.uniform_blocks, &r.storage_blocks, &r.push_constants})
    for (UniformBlock& block : *list)
      std::stable_sort(block.members.begin(), block.members.end(),
                       [](const BlockMember& a, const BlockMember& b) { return a.offset < b.offset; });

  auto interface = [&](bool outputs) {
    std::vector<InterfaceVariable> vars;
    std::map<uint32_t, std::string> semantics =
        spirv::interface_semantics(spirv, outputs ? spirv::Interface::output : spirv::Interface::input);
    int count = outputs ? p.getNumPipeOutputs() : p.getNumPipeInputs();
    for (int i = 0; i < count; ++i) {
      const glslang::TObjectReflection& io = outputs ? p.getPipeOutput(i) : p.getPipeInput(i);
      const glslang::TType* t = io.getType();
      if (!t || t->getQualifier().builtIn != glslang::EbvNone) continue;
      InterfaceVariable v;
      v.name = detail::effect_name(io.name);
      v.location = location_of(*t);
      v.type = reflected_type(*t);
      if (auto it = semantics.find(v.location); it != semantics.end()) {
        v.semantic = it->second;
      } else if (const char* declared = t->getQualifier().semanticName) {
        // spirv-opt's legalization drops the UserSemantic of an input the code never reads
        // but keeps the variable: the declaration still names its semantic.
        v.semantic = declared;
        v.unread = true;
        for (char& c : v.semantic) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      }
      vars.push_back(std::move(v));
    }
    std::sort(vars.begin(), vars.end(),
              [](const InterfaceVariable& a, const InterfaceVariable& b) { return a.location < b.location; });
    number_array_elements(vars);
    return vars;
  };
  r.inputs = interface(false);
  r.outputs = interface(true);

  if (const glslang::TIntermediate* im = p.getIntermediate(stage); im && stage == EShLangCompute)
    for (int d = 0; d < 3; ++d) r.local_size[d] = im->getLocalSize(d);
  return r;
}

}  // namespace fx

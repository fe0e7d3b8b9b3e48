// What a compiled stage exposes to the application: resources, vertex inputs, push constants.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fx/compile/translation_unit.h"

namespace fx {

// Scalar kind of a reflected variable.
enum class ScalarKind : uint8_t { float32, float16, float64, int32, uint32, boolean, other };

// Type of a reflected variable: scalar/vector/matrix shape plus array size.
struct ReflectedType {
  ScalarKind scalar = ScalarKind::float32;
  uint8_t rows = 1;         // 1 for scalars and vectors
  uint8_t columns = 1;      // vector size for vectors; GLSL-style columns for matrices
  bool is_struct = false;   // members are listed flattened with their own offsets
  uint32_t array_size = 0;  // 0 when not an array
  std::string glsl_name;    // "vec3", "mat4", "float" as glslang names it (for messages)
};

// Storage order of a matrix member as Vulkan sees it (SPIR-V decoration).
enum class MatrixLayout : uint8_t { none, column_major, row_major };

// One member of a uniform block, flattened ("light.dir" for struct members).
struct BlockMember {
  std::string name;
  ReflectedType type;
  uint32_t offset = 0;         // bytes from the block start
  uint32_t size = 0;           // bytes, arrays included
  uint32_t array_stride = 0;   // bytes between array elements; 0 when not an array
  uint32_t matrix_stride = 0;  // bytes between matrix columns (or rows when row_major)
  MatrixLayout matrix_layout = MatrixLayout::none;
};

// A uniform buffer (HLSL cbuffer or the implicit $Global block; GLSL uniform block).
struct UniformBlock {
  std::string name;
  uint32_t set = 0, binding = 0;
  uint32_t size = 0;                 // bytes
  std::vector<BlockMember> members;  // in offset order
  bool written = false;              // storage blocks: not readonly (RWStructuredBuffer, a counter)
};

// Image dimension of a texture or combined sampler.
enum class ImageDim : uint8_t { dim_1d, dim_2d, dim_3d, cube, buffer, other };

// A texture, sampler or combined image-sampler binding.
struct ImageBinding {
  enum class Kind : uint8_t { combined_image_sampler, sampled_image, sampler, storage_image };
  std::string name;
  Kind kind = Kind::combined_image_sampler;
  ImageDim dim = ImageDim::dim_2d;
  bool arrayed = false;  // texture arrays (Texture2DArray, sampler2DArray)
  bool shadow = false;   // comparison samplers
  uint32_t set = 0, binding = 0;
  uint32_t array_size = 0;    // descriptor count of an array of textures; 0 when not an array
  bool multisampled = false;  // Texture2DMS, Texture2DMSArray (SPIR-V OpTypeImage MS=1)
  // What a read returns: float32, or int32/uint32 for Texture2D<int>/<uint> (the view's
  // format must be of the same numeric type).
  ScalarKind sampled = ScalarKind::float32;
};

// A stage input or output (vertex attributes are the vertex stage's inputs), with its HLSL
// semantic when the source is HLSL. Built-ins (SV_Position, gl_FragCoord) are not listed.
struct InterfaceVariable {
  std::string name;
  uint32_t location = 0;
  ReflectedType type;
  std::string semantic;  // upper-case, e.g. "POSITION", "TEXCOORD0"; empty for GLSL
  // The code never reads it (spirv-opt dropped its semantic decoration; the semantic is the
  // declaration's): linking places it but does not warn that nothing writes it.
  bool unread = false;
};

// Everything reflected from one stage.
struct ShaderReflection {
  ShaderStage stage = ShaderStage::vertex;
  std::string entry_point;
  std::vector<UniformBlock> uniform_blocks;
  std::vector<UniformBlock> storage_blocks;  // HLSL (RW)StructuredBuffer / GLSL buffer
  std::vector<ImageBinding> images;
  std::vector<InterfaceVariable> inputs;     // by location (vertex attributes for VS)
  std::vector<InterfaceVariable> outputs;    // by location (colour attachments for PS)
  std::vector<UniformBlock> push_constants;  // at most one block in practice
  uint32_t local_size[3] = {0, 0, 0};        // compute workgroup size
};

}  // namespace fx

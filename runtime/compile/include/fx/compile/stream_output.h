// Stream output (ConstructGSWithSO): a pass stage's declarations as the effect writes them,
// and the capture fxkit patches into that stage's SPIR-V for VK_EXT_transform_feedback.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fx/ast.h"
#include "fx/compile/shader_compiler.h"
#include "fx/diagnostic.h"
#include "fx/source_manager.h"
#include "fx/stream_out_decl.h"

namespace fx {

// One declaration entry, the stream its string declares (fx_5_0 takes one string per
// stream) and where the entry is written.
struct StreamOutputEntry {
  StreamOutEntry entry;
  uint32_t stream = 0;
  SourceRange range;
};

// ConstructGSWithSO's arguments after the shader.
struct StreamOutputDecl {
  std::vector<StreamOutputEntry> entries;  // every declaration string's, in order
  int32_t rasterized_stream = 0;           // fx_5_0's last argument; -1: none
  SourceRange range;                       // the ConstructGSWithSO call
};

// Reads the declarations of `construct` (a ConstructGSWithSO call); entries that do not parse
// are left out (the checker reports them as bad-stream-out-decl).
StreamOutputDecl stream_output_decl(const ast::Expr& construct, const SourceManager& sm);

// One captured output and where each vertex holds it in its output buffer.
struct CapturedOutput {
  std::string semantic;  // as the declaration names it, index appended ("TEXCOORD1"); "SV_POSITION"
  uint32_t slot = 0;     // output buffer
  uint32_t offset = 0;   // bytes from the vertex's start
  uint32_t components = 0;
  ScalarKind scalar = ScalarKind::float32;
};

// What a capturing stage writes into its output buffers.
struct StreamOutputLayout {
  std::vector<CapturedOutput> outputs;
  std::array<uint32_t, kStreamOutSlots> strides{};  // bytes per vertex of each buffer; 0: unused
  bool rasterized = true;  // false: rasterized stream -1, the pass draws nothing while capturing
  // Why the pass cannot run as declared ("" when it can): a declaration for a stream other
  // than 0, or a rasterized stream other than 0 or -1, which glslang cannot write; where.
  std::string unsupported;
  SourceRange unsupported_range;
};

// Decorates the outputs of `shader` (the last stage before rasterization, after
// link_program) that `decl` captures: XfbBuffer, XfbStride and Offset on each, the Xfb
// execution mode. Vulkan captures whole output variables, so an entry's mask must be all of
// its output's components ("NORMAL.xyz" or "NORMAL" of a float3); a narrower mask and an
// output the stage does not write are located errors ("unsupported-stream-output-decl") and
// nothing is returned. A stream other than 0 and a rasterized stream other than 0 or -1 (fxc
// accepts them; glslang writes one stream) are warnings ("unsupported-stream-output-stream")
// and the layout's `unsupported`: the pass compiles and is refused at run time.
std::optional<StreamOutputLayout> capture_stream_output(CompiledShader& shader, const StreamOutputDecl& decl,
                                                        DiagnosticSink& sink);

}  // namespace fx

// The shader model 1 instruction table: every vs.1.1 and ps.1.0-1.4 instruction with its
// operand count and the versions that have it (the DirectX 8.1 reference's lists).
#include "assembly_ops.h"

namespace fx::emulation {
namespace {

constexpr OpInfo kOps[] = {
    // name, dest, sources, vertex, ps_min, ps_max, optional_last
    {"nop", false, 0, true, 0, 4},
    {"phase", false, 0, false, 4, 4},
    {"def", true, 0, true, 0, 4},
    {"dcl", true, 0, true, -1, -1},
    {"mov", true, 1, true, 0, 4},
    {"add", true, 2, true, 0, 4},
    {"sub", true, 2, true, 0, 4},
    {"mul", true, 2, true, 0, 4},
    {"mad", true, 3, true, 0, 4},
    {"dp3", true, 2, true, 0, 4},
    {"dp4", true, 2, true, 2, 4},
    {"lrp", true, 3, false, 0, 4},
    {"cnd", true, 3, false, 0, 4},
    {"cmp", true, 3, false, 2, 4},
    {"bem", true, 2, false, 4, 4},
    {"min", true, 2, true, -1, -1},
    {"max", true, 2, true, -1, -1},
    {"slt", true, 2, true, -1, -1},
    {"sge", true, 2, true, -1, -1},
    {"rcp", true, 1, true, -1, -1},
    {"rsq", true, 1, true, -1, -1},
    {"exp", true, 1, true, -1, -1},
    {"expp", true, 1, true, -1, -1},
    {"log", true, 1, true, -1, -1},
    {"logp", true, 1, true, -1, -1},
    {"lit", true, 1, true, -1, -1},
    {"dst", true, 2, true, -1, -1},
    {"frc", true, 1, true, -1, -1},
    {"m4x4", true, 2, true, -1, -1},
    {"m4x3", true, 2, true, -1, -1},
    {"m3x4", true, 2, true, -1, -1},
    {"m3x3", true, 2, true, -1, -1},
    {"m3x2", true, 2, true, -1, -1},
    // ps.1.0-1.3 texture address instructions: the destination is the stage's t register.
    {"tex", true, 0, false, 0, 3},
    {"texcoord", true, 0, false, 0, 3},
    {"texkill", true, 0, false, 0, 4},
    {"texbem", true, 1, false, 0, 3},
    {"texbeml", true, 1, false, 0, 3},
    {"texreg2ar", true, 1, false, 0, 3},
    {"texreg2gb", true, 1, false, 0, 3},
    {"texreg2rgb", true, 1, false, 2, 3},
    {"texm3x2pad", true, 1, false, 0, 3},
    {"texm3x2tex", true, 1, false, 0, 3},
    {"texm3x2depth", true, 1, false, 3, 3},
    {"texm3x3pad", true, 1, false, 0, 3},
    {"texm3x3tex", true, 1, false, 0, 3},
    {"texm3x3", true, 1, false, 2, 3},
    {"texm3x3spec", true, 2, false, 0, 3},
    {"texm3x3vspec", true, 1, false, 0, 3},
    {"texdp3", true, 1, false, 2, 3},
    {"texdp3tex", true, 1, false, 2, 3},
    // ps.1.4.
    {"texld", true, 1, false, 4, 4},
    {"texcrd", true, 1, false, 4, 4},
    {"texdepth", true, 0, false, 4, 4},
};

}  // namespace

const OpInfo* find_op(std::string_view name) {
  for (const OpInfo& op : kOps)
    if (op.name == name) return &op;
  return nullptr;
}

}  // namespace fx::emulation

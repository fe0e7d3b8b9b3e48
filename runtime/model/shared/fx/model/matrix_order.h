// fxkit::MatrixOrder: how the application's 16 matrix floats are ordered, shared by the
// parameter store (fx::ParameterStore::set_matrix) and the public API (fxkit::Effect).
#pragma once
#include <cstdint>

namespace fxkit {

// row_major = m[r][c] at r * 4 + c (D3DX; the memory of a glm::mat4 M used as M * v is HLSL's
// matrix in mul(v, M)); column_major = the effect's matrix column by column (transposed on
// set). Not the HLSL packing of a matrix in a constant buffer: that is fx::MatrixPacking.
enum class MatrixOrder : uint8_t { row_major, column_major };

}  // namespace fxkit

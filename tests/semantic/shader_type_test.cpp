// Built-in shader types by name, swizzles and element types.
#include "fx/shader_type.h"

#include <gtest/gtest.h>

#include "fx/intrinsics.h"

namespace {

using namespace fx::semantic;

TEST(ShaderType, BuiltinNumericTypes) {
  EXPECT_EQ(builtin_numeric_type("float")->kind, TypeClass::scalar);
  EXPECT_EQ(builtin_numeric_type("half3")->columns, 3);
  auto m = builtin_numeric_type("float4x3");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->kind, TypeClass::matrix);
  EXPECT_EQ(m->rows, 4);
  EXPECT_EQ(m->columns, 3);
  EXPECT_FALSE(builtin_numeric_type("float5"));
  EXPECT_FALSE(builtin_numeric_type("floaty"));
  EXPECT_TRUE(is_object_type_name("texture2D"));
  EXPECT_TRUE(is_object_type_name("Texture2D"));
  EXPECT_FALSE(is_object_type_name("Light"));
}

TEST(ShaderType, Swizzles) {
  const ShaderType v3 = *builtin_numeric_type("float3");
  EXPECT_EQ(swizzle_type(v3, "xy")->name, "float2");
  EXPECT_EQ(swizzle_type(v3, "bgr")->name, "float3");
  EXPECT_EQ(swizzle_type(v3, "x")->kind, TypeClass::scalar);
  EXPECT_FALSE(swizzle_type(v3, "w"));      // beyond its size
  EXPECT_FALSE(swizzle_type(v3, "xg"));     // two sets mixed
  EXPECT_FALSE(swizzle_type(v3, "xyzxy"));  // five components
  const ShaderType scalar = *builtin_numeric_type("float");
  EXPECT_EQ(swizzle_type(scalar, "xxxx")->name, "float4");
  const ShaderType m = *builtin_numeric_type("float4x4");
  EXPECT_EQ(swizzle_type(m, "_m00_m11")->name, "float2");
  EXPECT_EQ(swizzle_type(m, "_44")->kind, TypeClass::scalar);
  EXPECT_FALSE(swizzle_type(m, "_m44"));
  EXPECT_EQ(element_type(m).name, "float4");
}

TEST(Intrinsics, OneSortedTable) {
  ASSERT_NE(find_intrinsic("tex2D"), nullptr);
  EXPECT_EQ(find_intrinsic("mul")->name, "mul");
  EXPECT_EQ(find_intrinsic("Mul"), nullptr);  // HLSL intrinsics are case-sensitive
  EXPECT_GT(all_intrinsics().size(), 100u);
}

}  // namespace

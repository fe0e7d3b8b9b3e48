// Scene parameters known by their semantic's abbreviations and by their names' decorations:
// what fxkit render binds in effects written for other tools.
#include <gtest/gtest.h>

#include "fx/binding/effect_scene.h"

namespace fx::vk {
namespace {

TEST(SceneSemantics, AbbreviatedTransformSemanticsAreTheStandardOnes) {
  EXPECT_EQ(standard_semantic("WorldViewProj"), "WORLDVIEWPROJECTION");  // NVIDIA's and 3ds Max's
  EXPECT_EQ(standard_semantic("VIEWPROJ"), "VIEWPROJECTION");
  EXPECT_EQ(standard_semantic("WorldI"), "WORLDINVERSE");
  EXPECT_EQ(standard_semantic("VIEWINV"), "VIEWINVERSE");
  EXPECT_EQ(standard_semantic("WorldIT"), "WORLDINVERSETRANSPOSE");
  EXPECT_EQ(standard_semantic("ViewInverseTranspose"), "VIEWINVERSETRANSPOSE");
  EXPECT_EQ(standard_semantic("WORLDVIEWPROJI"), "WORLDVIEWPROJECTIONINVERSE");
  EXPECT_EQ(standard_semantic("ProjInverse"), "PROJECTIONINVERSE");
  // Other semantics are only upper-cased; a suffix alone is no transform.
  EXPECT_EQ(standard_semantic("CameraPosition"), "CAMERAPOSITION");
  EXPECT_EQ(standard_semantic("Diffuse"), "DIFFUSE");
  EXPECT_EQ(standard_semantic("I"), "I");
  EXPECT_EQ(standard_semantic("POSITIONI"), "POSITIONI");
}

TEST(SceneSemantics, TransformNamesWithOtherDecorationsAreKnown) {
  EXPECT_EQ(semantic_by_name("g_mWorldViewProjection"), "WORLDVIEWPROJECTION");  // the table
  EXPECT_EQ(semantic_by_name("WorldViewProjMatrix"), "WORLDVIEWPROJECTION");     // Kodu, engines
  EXPECT_EQ(semantic_by_name("WorldMatrix"), "WORLD");
  EXPECT_EQ(semantic_by_name("g_f4x4World"), "WORLD");
  EXPECT_EQ(semantic_by_name("g_m4x4WorldViewProjection"), "WORLDVIEWPROJECTION");
  EXPECT_EQ(semantic_by_name("mWorldViewProjection"), "WORLDVIEWPROJECTION");
  EXPECT_EQ(semantic_by_name("g_mInvView"), "VIEWINVERSE");
  EXPECT_EQ(semantic_by_name("g_mInvProj"), "PROJECTIONINVERSE");
  EXPECT_EQ(semantic_by_name("ViewProjMat"), "VIEWPROJECTION");
  EXPECT_EQ(semantic_by_name("gWorldXf"), "WORLD");
  EXPECT_EQ(semantic_by_name("WorldMatrixInverseTranspose"), "WORLDINVERSETRANSPOSE");  // Matrix inside
  // From one space to another: products going forward, inverses going back.
  EXPECT_EQ(semantic_by_name("ObjectToWorld"), "WORLD");
  EXPECT_EQ(semantic_by_name("WorldToCamera"), "VIEW");
  EXPECT_EQ(semantic_by_name("WorldToNDC"), "VIEWPROJECTION");
  EXPECT_EQ(semantic_by_name("g_mObjectToView"), "WORLDVIEW");
  EXPECT_EQ(semantic_by_name("ModelToClip"), "WORLDVIEWPROJECTION");
  EXPECT_EQ(semantic_by_name("CameraToWorld"), "VIEWINVERSE");
  EXPECT_EQ(semantic_by_name("ClipToObject"), "WORLDVIEWPROJECTIONINVERSE");
  // A previous frame's transform, an unrelated matrix and non-transforms stay unknown.
  EXPECT_EQ(semantic_by_name("g_mWorldPrev"), "");
  EXPECT_EQ(semantic_by_name("g_mShadowMatrix"), "");
  EXPECT_EQ(semantic_by_name("LocalToModel"), "");  // one space: a preview stand-in's identity
  EXPECT_EQ(semantic_by_name("WorldToShadow"), "");
  EXPECT_EQ(semantic_by_name("Tonemap"), "");
  EXPECT_EQ(semantic_by_name("Matrix"), "");
  EXPECT_EQ(semantic_by_name("gInv"), "");
  EXPECT_EQ(semantic_by_name("g_vLightDir"), "");
}

}  // namespace
}  // namespace fx::vk

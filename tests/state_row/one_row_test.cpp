// Adding a state is one row: with tests/state_row/one_row.inc compiled into the state table
// (and nothing else changed), the new state is parsed, its value checked, its row
// documented, and its value applied to the pass state and the Vulkan pipeline state.
#include <gtest/gtest.h>

#include "fx/binding/pass_state_mapping.h"
#include "fx/state_table.h"
#include "model_test_util.h"

namespace fx {
namespace {

TEST(OneStateRow, IsParsed) {
  const StateInfo* row = find_state("depthwriteenable", StateBlock::pass);
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->lands, StateLanding::pipeline);
  EXPECT_EQ(row->field, StateField::depth_write);
  auto b = test::build("technique T { pass P { DepthWriteEnable = FALSE; } }", true);
  EXPECT_FALSE(b->diags.has_errors()) << b->text();
}

TEST(OneStateRow, ItsValueIsChecked) {
  auto b = test::build("technique T { pass P { DepthWriteEnable = Sometimes; } }", true);
  EXPECT_TRUE(b->diags.has_errors());
  EXPECT_NE(b->text().find("DepthWriteEnable"), std::string::npos) << b->text();
}

TEST(OneStateRow, IsDocumented) {
  const std::string doc = render_state_table_markdown();
  EXPECT_NE(
      doc.find("| DepthWriteEnable | - | bool | D3D9 | maps_to_vulkan | depth_stencil | pipeline: `depth_write` |"),
      std::string::npos);
}

TEST(OneStateRow, IsAppliedToThePipeline) {
  auto b = test::build("technique T { pass P { ZWriteEnable = TRUE; DepthWriteEnable = FALSE; } }", true);
  ASSERT_FALSE(b->diags.has_errors()) << b->text();
  const PassStateSummary& s = b->model.techniques[0].passes[0].summary;
  EXPECT_FALSE(s.depth_write);
  DiagnosticSink sink;
  auto state = vk::to_pipeline_state(s, {}, vk::DeviceFeatures{}, sink);
  ASSERT_TRUE(state.has_value());
  EXPECT_EQ(state->depth_write, 0u);
}

}  // namespace
}  // namespace fx

// Which shard each merged material comes from, and how the inputs' root attributes join.
#include "merge/material_plan.hpp"

#include <gtest/gtest.h>

#include "core/sha256.hpp"
#include "merge/root_attributes.hpp"
#include "tests/support/bad_input.hpp"

namespace haptex::merge {
namespace {

using test::bad_input_message;

const std::vector<std::string> kPaths{"a.h5", "b.h5", "c.h5"};

TEST(MaterialPlan, TakesEveryMaterialSortedById) {
  const MaterialPlan plan = plan_materials({{"wood", "cork"}, {"brick"}}, kPaths, false);
  ASSERT_EQ(plan.materials.size(), 3u);
  EXPECT_EQ(plan.materials[0].id, "brick");
  EXPECT_EQ(plan.materials[0].shard, 1u);
  EXPECT_EQ(plan.materials[2].id, "wood");
  EXPECT_EQ(plan.taken_from(0), (std::vector<std::string>{"cork", "wood"}));
  EXPECT_TRUE(plan.left_out.empty());
  EXPECT_EQ(id_list(plan.taken_from(0)), "cork wood");
}

TEST(MaterialPlan, RefusesAMaterialInTwoShardsNamingBothAndTheMaterial) {
  const std::string message = bad_input_message([] { plan_materials({{"cork"}, {"felt"}, {"cork", "glass"}}, kPaths, false); });
  EXPECT_NE(message.find("c.h5: /materials/cork"), std::string::npos) << message;
  EXPECT_NE(message.find("also in a.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("--keep-first"), std::string::npos) << message;
}

TEST(MaterialPlan, KeepFirstTakesTheFirstShardsCopyAndSaysWhichWasLeftOut) {
  const MaterialPlan plan = plan_materials({{"cork"}, {"cork", "felt"}, {"cork"}}, kPaths, true);
  ASSERT_EQ(plan.materials.size(), 2u);
  EXPECT_EQ(plan.materials[0].shard, 0u);
  ASSERT_EQ(plan.left_out.size(), 2u);
  EXPECT_EQ(plan.left_out[0].shard, 1u);
  EXPECT_EQ(plan.left_out[1].shard, 2u);
  EXPECT_EQ(plan.left_out[1].kept_from, 0u);
  EXPECT_TRUE(plan.contributes(1));
  EXPECT_FALSE(plan.contributes(2)) << "every material of c.h5 came from a.h5";
  EXPECT_EQ(plan.left_out_of(2), std::vector<std::string>{"cork"});
}

TEST(RootAttributes, NamesJoinAsLinesAndHashesAsOneHash) {
  EXPECT_EQ(join_values(Join::lines, {"r1.h5", "r2.h5", "r1.h5"}), "r1.h5\nr2.h5");
  EXPECT_EQ(join_values(Join::lines, {"same", "same"}), "same");
  const std::string a(64, 'a'), b(64, 'b');
  EXPECT_EQ(join_values(Join::digest, {a, a}), a) << "one input is named by its own hash";
  EXPECT_EQ(join_values(Join::digest, {b, a, b}), sha256_hex(std::string_view(a + "\n" + b + "\n")));
  EXPECT_EQ(join_values(Join::digest, {a, b}), join_values(Join::digest, {b, a})) << "the same inputs in any order";
}

}  // namespace
}  // namespace haptex::merge

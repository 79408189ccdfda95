// Model helpers and direction names.
#include <gtest/gtest.h>

#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {
namespace {

constexpr double kMassTolerance = 1e-12;  // [kg], sums of a few exact products

TEST(Direction, NamesAndParsingAreInverse) {
  for (int d = 0; d < kDofsPerNode; ++d) {
    EXPECT_EQ(parseDirection(directionName(d)), d);
  }
  EXPECT_STREQ(directionName(static_cast<int>(Direction::Uz)), "uz");
  EXPECT_STREQ(directionName(static_cast<int>(Direction::Rx)), "rx");
  EXPECT_EQ(parseDirection("RZ"), 5);
  EXPECT_EQ(parseDirection("Uy"), 1);
  EXPECT_EQ(parseDirection("uw"), -1);
  EXPECT_EQ(parseDirection("ux "), -1);
  EXPECT_EQ(parseDirection(""), -1);
  EXPECT_STREQ(directionName(6), "?");
  EXPECT_STREQ(directionName(-1), "?");
}

TEST(Model, NodeIndexMapsIdsToPositions) {
  Model model;
  EXPECT_EQ(model.addNode(10, Vector3(0, 0, 0)), 10);
  model.addNode(-7, Vector3(1, 0, 0));
  model.addNode(3, Vector3(2, 0, 0));
  const auto index = model.nodeIndex();
  ASSERT_EQ(index.size(), 3u);
  EXPECT_EQ(index.at(10), 0u);
  EXPECT_EQ(index.at(-7), 1u);
  EXPECT_EQ(index.at(3), 2u);
  EXPECT_EQ(model.nodes[2].position, Vector3(2, 0, 0));
}

TEST(Model, NodeIndexRejectsDuplicateIds) {
  Model model;
  model.addNode(1, Vector3::Zero());
  model.addNode(2, Vector3::UnitX());
  model.addNode(1, Vector3::UnitY());
  try {
    model.nodeIndex();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "model: nodes[2]: duplicate node id 1 (also nodes[0])");
  }
}

TEST(Model, FindsMaterialsAndSectionsByName) {
  Model model;
  model.materials.push_back({"steel", 210e9, 81e9, 7850});
  model.materials.push_back({"alu", 69e9, 26e9, 2700});
  model.sections.push_back({"tube", 1e-4, 1e-8, 1e-8, 2e-8, 0, 0});
  ASSERT_NE(model.findMaterial("alu"), nullptr);
  EXPECT_EQ(model.findMaterial("alu")->density, 2700);
  EXPECT_EQ(model.findMaterial("Alu"), nullptr);
  ASSERT_NE(model.findSection("tube"), nullptr);
  EXPECT_EQ(model.findSection("tube")->iz, 1e-8);
  EXPECT_EQ(model.findSection("rod"), nullptr);
}

TEST(Model, TotalMassSumsMassesAndBeams) {
  Model model;
  EXPECT_EQ(model.totalMass(), 0.0);
  model.addNode(1, Vector3(0, 0, 0));
  model.addNode(2, Vector3(3, 4, 0));  // 5 m away
  model.addNode(3, Vector3(3, 4, 2));  // 2 m further
  model.materials.push_back({"steel", 210e9, 81e9, 8000});
  model.materials.push_back({"light", 70e9, 26e9, 1000});
  model.sections.push_back({"a", 1e-3, 1e-8, 1e-8, 2e-8, 0, 0});
  model.beams.push_back({1, 2, "steel", "a", Vector3::UnitZ()});
  model.beams.push_back({2, 3, "light", "a", Vector3::UnitX()});
  model.masses.push_back({3, 2.5, Matrix3::Identity(), Vector3::Zero(), "m"});
  // 8000 * 1e-3 * 5 + 1000 * 1e-3 * 2 + 2.5
  EXPECT_NEAR(model.totalMass(), 40.0 + 2.0 + 2.5, kMassTolerance);
}

TEST(Model, TotalMassNamesAnUnresolvableBeam) {
  Model model;
  model.addNode(1, Vector3(0, 0, 0));
  model.addNode(2, Vector3(1, 0, 0));
  model.sections.push_back({"a", 1e-3, 1e-8, 1e-8, 2e-8, 0, 0});
  model.beams.push_back({1, 2, "steel", "a", Vector3::UnitZ()});
  try {
    model.totalMass();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "model: beams[0]: material 'steel' does not exist");
  }
}

}  // namespace
}  // namespace fem
}  // namespace tracked_vehicle_dynamics

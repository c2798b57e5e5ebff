// The funnel's stages (funnel.hpp): the first stage an object did not pass, and the table.
#include "funnel.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace vsl::tools {
namespace {

FunnelSide clean() {
  FunnelSide s;
  s.blob = 3;
  s.purity = 0.99;
  s.coverage = 0.9;
  s.detected = true;
  return s;
}

TEST(Funnel, FirstStageNotPassed) {
  EXPECT_EQ(funnel_stage(clean(), clean(), true), FunnelStage::kPercept);
  EXPECT_EQ(funnel_stage(clean(), clean(), false), FunnelStage::kStereo);
  FunnelSide none = clean();
  none.blob = -1;
  EXPECT_EQ(funnel_stage(clean(), none, false), FunnelStage::kNoBlob);
  FunnelSide merged = clean();
  merged.purity = 0.6;
  EXPECT_EQ(funnel_stage(merged, clean(), false), FunnelStage::kMerged);
  FunnelSide piece = merged;
  piece.purity = 1.0;
  piece.coverage = 0.4;
  EXPECT_EQ(funnel_stage(clean(), piece, false), FunnelStage::kFragment);
  // Merged comes first: a blob both joined to another object and holding a piece of this one.
  merged.coverage = 0.4;
  EXPECT_EQ(funnel_stage(merged, clean(), false), FunnelStage::kMerged);
  FunnelSide missed = clean();
  missed.detected = false;
  EXPECT_EQ(funnel_stage(missed, clean(), false), FunnelStage::kUndetected);
  missed.at_border = true;
  EXPECT_EQ(funnel_stage(clean(), missed, false), FunnelStage::kUndetectedAtBorder);
  // A border blob that was detected is not what lost the object.
  FunnelSide border = clean();
  border.at_border = true;
  FunnelSide inside_missed = clean();
  inside_missed.detected = false;
  EXPECT_EQ(funnel_stage(border, inside_missed, false), FunnelStage::kUndetected);
}

TEST(Funnel, TableCountsPerClassAndWholeOrCutWithTheStereoGates) {
  FunnelTally tally;
  tally.add("door", true, FunnelStage::kPercept, "no_pair");
  tally.add("door", true, FunnelStage::kStereo, "rectangle_fit");
  tally.add("door", true, FunnelStage::kStereo, "epipolar");
  tally.add("door", true, FunnelStage::kStereo, "rectangle_fit");
  tally.add("door", false, FunnelStage::kUndetectedAtBorder, "no_pair");
  std::ostringstream out;
  tally.print(out);
  const std::string text = out.str();
  EXPECT_NE(text.find("door    whole       4        1       0       0        0       3          "
                      "0          0"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("door    cut         1        0       0       0        0       0          "
                      "1          0"),
            std::string::npos)
      << text;
  EXPECT_NE(
      text.find("door whole, detected in both images without a true percept: rectangle_fit 2, "
                "epipolar 1"),
      std::string::npos)
      << text;
  EXPECT_EQ(text.find("door cut, detected"), std::string::npos) << text;
}

}  // namespace
}  // namespace vsl::tools

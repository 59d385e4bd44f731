// util/driver_defects: which devices get PPR's driver warning (lavapipe at a width other than its
// default 8 lanes) and that the line names the setting and the damage.
#include "util/driver_defects.hpp"

#include <gtest/gtest.h>

namespace ppr::util {
namespace {

TEST(LavapipeWidth, ItsDefaultEightLanesNeedNoWarning) {
    EXPECT_EQ(lavapipeWidthWarning("cpu", "llvmpipe (LLVM 15.0.6, 256 bits)", 8), "");
}

TEST(LavapipeWidth, SixteenLanesNameTheSettingAndWhatGoesWrong) {
    std::string w = lavapipeWidthWarning("cpu", "llvmpipe (LLVM 15.0.6, 512 bits)", 16);
    EXPECT_NE(w.find("16-lane"), std::string::npos) << w;
    EXPECT_NE(w.find("LP_NATIVE_VECTOR_WIDTH=512"), std::string::npos) << w;
    EXPECT_NE(w.find("half of every tile"), std::string::npos) << w;
    EXPECT_EQ(w.find('\n'), std::string::npos) << "one line";
    EXPECT_NE(lavapipeWidthWarning("cpu", "llvmpipe (LLVM 15.0.6, 1024 bits)", 32).find("LP_NATIVE_VECTOR_WIDTH=1024"), std::string::npos);
}

TEST(LavapipeWidth, OtherDevicesAreLeftAlone) {
    EXPECT_EQ(lavapipeWidthWarning("discrete", "NVIDIA H100 80GB HBM3", 32), "");
    EXPECT_EQ(lavapipeWidthWarning("integrated", "AMD Radeon Graphics (RADV GFX1103_R1)", 64), "");
    EXPECT_EQ(lavapipeWidthWarning("cpu", "SwiftShader Device (LLVM 10.0.0)", 4), "");
}

}  // namespace
}  // namespace ppr::util

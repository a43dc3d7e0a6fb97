#include <engine/Error.h>
#include <engine/ShaderVariantKey.h>

#include <gtest/gtest.h>

using namespace engine;

TEST(ShaderVariantKeyTest, FlagsAreStableDistinctBits) {
    ShaderVariantLayout layout;
    const ShaderVariantKey a = layout.flag("GS_A");
    const ShaderVariantKey b = layout.flag("GS_B");
    EXPECT_EQ(a, 1u);
    EXPECT_EQ(b, 2u);
    EXPECT_EQ(layout.flag("GS_A"), a);
    EXPECT_EQ(layout.flagCount(), 2u);
}

TEST(ShaderVariantKeyTest, DefinesFollowSetBitsOnly) {
    ShaderVariantLayout layout;
    const ShaderVariantKey a = layout.flag("GS_A");
    layout.flag("GS_B");
    const ShaderVariantKey c = layout.flag("GS_C");
    EXPECT_EQ(layout.defines(a | c), (std::vector<std::string>{"#define GS_A 1", "#define GS_C 1"}));
    EXPECT_TRUE(layout.defines(0).empty());
}

TEST(ShaderVariantKeyTest, RejectsInvalidNamesAndOverflow) {
    ShaderVariantLayout layout;
    for (const char* bad : {"", "1ABC", "HAS SPACE", "A-B"}) {
        EXPECT_THROW(layout.flag(bad), Error) << bad;
    }
    for (int i = 0; i < ShaderVariantLayout::kMaxFlags; ++i) {
        layout.flag("F" + std::to_string(i));
    }
    EXPECT_EQ(layout.flag("F63"), ShaderVariantKey{1} << 63);
    try {
        layout.flag("ONE_TOO_MANY");
        FAIL();
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("ONE_TOO_MANY"), std::string::npos);
    }
}

// The technique table: one row per technique, in enum order, with what the passes need (no GL).
#include "GeneratedDocs.h"

#include <shadows/ShadowSettings.h>
#include <shadows/ShadowTechniqueTraits.h>

#include <gtest/gtest.h>

#include <set>

using namespace shadows;

TEST(ShadowTechniqueTraitsTest, OneRowPerTechniqueInEnumOrder) {
    const auto table = techniqueTable();
    ASSERT_EQ(table.size(), kTechniqueCount);
    ASSERT_EQ(allTechniques().size(), kTechniqueCount);
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(static_cast<std::size_t>(table[i].technique), i);
        EXPECT_EQ(&traitsOf(table[i].technique), &table[i]);
        EXPECT_FALSE(table[i].defines[0].empty()) << table[i].name;
        EXPECT_FALSE(table[i].summary.empty()) << table[i].name;
        EXPECT_TRUE(names.insert(table[i].name).second) << table[i].name;
    }
}

TEST(ShadowTechniqueTraitsTest, FilteredMapsAreSampledAsMoments) {
    for (const ShadowTechniqueTraits& traits : techniqueTable()) {
        EXPECT_EQ(traits.sampler == MapSampler::Moments || traits.sampler == MapSampler::MomentMips,
                  traits.moments.format != nullptr)
            << traits.name;
    }
}

TEST(ShadowTechniqueTraitsTest, NamesRoundTrip) {
    for (const ShadowTechnique technique : allTechniques()) {
        EXPECT_EQ(techniqueFromString(toString(technique)), technique);
    }
    EXPECT_FALSE(techniqueFromString("shadow-volumes"));
    EXPECT_EQ(depthFormatFromString("d16"), DepthFormat::D16);
    EXPECT_FALSE(depthFormatFromString("d8"));
}

TEST(ShadowTechniqueTraitsTest, DocsAndReadmeTechniqueTablesAreGenerated) {
    expectGeneratedSection("docs/SHADOWS.md", "techniques", techniqueMarkdownTable());
    expectGeneratedSection("README.md", "techniques", techniqueMarkdownTable());
}

#include <engine/Error.h>
#include <engine/ModuleLoader.h>

#include <gtest/gtest.h>

using namespace engine;

namespace {

std::string loadError(std::string_view name) {
    try {
        ModuleLoader loader;
        (void)loader.load(name);
    } catch (const ModuleError& error) {
        return error.what();
    }
    return "(loaded without error)";
}

bool contains(const std::string& text, const std::string& needle) {
    return text.find(needle) != std::string::npos;
}

ModuleDescriptor validDescriptor() {
    return {kModuleAbiVersion, GS_MODULE_BUILD_TAG, "probe", []() -> Module* { return nullptr; },
            [](Module*) {}};
}

} // namespace

TEST(ModuleDescriptorTest, AcceptsMatchingDescriptor) {
    EXPECT_EQ(checkModuleDescriptor(validDescriptor(), "probe"), "");
}

TEST(ModuleDescriptorTest, ExplainsEachMismatch) {
    ModuleDescriptor descriptor = validDescriptor();
    descriptor.abiVersion = kModuleAbiVersion + 3;
    EXPECT_TRUE(contains(checkModuleDescriptor(descriptor, "probe"),
                         "ABI version " + std::to_string(kModuleAbiVersion + 3)));

    descriptor = validDescriptor();
    descriptor.buildTag = "msvc-19";
    EXPECT_TRUE(contains(checkModuleDescriptor(descriptor, "probe"), "built with 'msvc-19'"));

    descriptor = validDescriptor();
    EXPECT_TRUE(contains(checkModuleDescriptor(descriptor, "shadows"), "calls itself 'probe'"));

    descriptor = validDescriptor();
    descriptor.create = nullptr;
    EXPECT_TRUE(contains(checkModuleDescriptor(descriptor, "probe"), "create or destroy"));
}

TEST(ModuleLoaderTest, FileNameFollowsConvention) {
    EXPECT_EQ(ModuleLoader::fileNameFor("shadows"), "libgs_module_shadows.so");
}

TEST(ModuleLoaderTest, LoadsTheProbeFromTheBuildTree) {
    ModuleLoader loader;
    auto loaded = loader.load("probe");
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->module().name(), "probe");
    EXPECT_EQ(loaded->path().filename(), "libgs_module_probe.so");
}

TEST(ModuleLoaderTest, MissingModuleNamesFileAndSearchedFolders) {
    const std::string message = loadError("does_not_exist");
    EXPECT_TRUE(contains(message, "module 'does_not_exist' not found")) << message;
    EXPECT_TRUE(contains(message, "libgs_module_does_not_exist.so")) << message;
    EXPECT_TRUE(contains(message, "GS_MODULE_PATH")) << message;
}

TEST(ModuleLoaderTest, WrongAbiIsRefusedWithBothVersions) {
    const std::string message = loadError("wrong_abi");
    EXPECT_TRUE(contains(message, "libgs_module_wrong_abi.so")) << message;
    EXPECT_TRUE(contains(message, "ABI version " + std::to_string(kModuleAbiVersion + 1) +
                                      " does not match the engine's " + std::to_string(kModuleAbiVersion)))
        << message;
}

TEST(ModuleLoaderTest, LibraryWithoutDescriptorIsNotAModule) {
    const std::string message = loadError("not_a_module");
    EXPECT_TRUE(contains(message, "is not an engine module")) << message;
}

TEST(ModuleLoaderTest, InvalidNamesAreRefusedBeforeSearching) {
    for (const char* name : {"", "../evil", "Upper", "a/b"}) {
        EXPECT_TRUE(contains(loadError(name), "a module name uses only")) << name;
    }
}

TEST(ModuleLoaderTest, SearchPathsPutExplicitFoldersFirst) {
    ModuleLoader loader;
    loader.addSearchPath("/explicit/first");
    const auto paths = loader.searchPaths();
    ASSERT_FALSE(paths.empty());
    EXPECT_EQ(paths.front(), "/explicit/first");
}

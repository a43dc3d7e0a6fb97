#pragma once

#include <engine/Module.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

/// @brief A module instance created from a shared library; destroys the module before closing the library.
class LoadedModule {
public:
    LoadedModule(void* library, const ModuleDescriptor& descriptor, std::filesystem::path path);
    ~LoadedModule();
    LoadedModule(const LoadedModule&) = delete;
    LoadedModule& operator=(const LoadedModule&) = delete;

    [[nodiscard]] Module& module() const { return *module_; }
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    /// @brief Address of another exported symbol of the library, or nullptr.
    [[nodiscard]] void* symbol(const char* name) const;

private:
    void* library_;
    const ModuleDescriptor& descriptor_;
    std::filesystem::path path_;
    Module* module_;
};

/// @brief Finds module shared libraries by name (`libgs_module_<name>.so`) and checks their ABI.
///
/// Search order: folders given to addSearchPath, then each folder of $GS_MODULE_PATH (colon-separated),
/// then the running executable's folder, its `../lib` and, for an installed executable, the installed library
/// folder (found relative to it, so a moved prefix still works).
class ModuleLoader {
public:
    ModuleLoader();
    void addSearchPath(std::filesystem::path folder);

    /// @brief The file a module name maps to, e.g. "shadows" → "libgs_module_shadows.so".
    static std::string fileNameFor(std::string_view moduleName);

    /// @brief Loads and instantiates module `name`. Throws ModuleError naming the module and, where one
    /// was found, the file: not found (listing the folders searched), not a loadable library, no
    /// `gsModuleDescriptor` export, ABI version or build tag mismatch, or a name mismatch.
    [[nodiscard]] std::unique_ptr<LoadedModule> load(std::string_view name) const;

    [[nodiscard]] std::vector<std::filesystem::path> searchPaths() const;

private:
    std::vector<std::filesystem::path> extraPaths_;
};

/// @brief Checks a descriptor against this engine; returns an empty string when it is compatible,
/// otherwise the reason. Pure function, unit-tested without loading anything.
std::string checkModuleDescriptor(const ModuleDescriptor& descriptor, std::string_view expectedName);

} // namespace engine

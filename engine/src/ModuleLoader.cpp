#include <engine/Error.h>
#include <engine/ModuleLoader.h>

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace engine {

namespace {

bool isValidModuleName(std::string_view name) {
    return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
        return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
               c == '_' || c == '-';
    });
}

std::filesystem::path executableFolder() {
    std::error_code error;
    const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path{} : executable.parent_path();
}

} // namespace

std::string checkModuleDescriptor(const ModuleDescriptor& descriptor, std::string_view expectedName) {
    std::ostringstream reason;
    if (descriptor.abiVersion != kModuleAbiVersion) {
        reason << "module ABI version " << descriptor.abiVersion << " does not match the engine's "
               << kModuleAbiVersion << " (rebuild the module against this engine)";
    } else if (!descriptor.buildTag || std::strcmp(descriptor.buildTag, GS_MODULE_BUILD_TAG) != 0) {
        reason << "module was built with '" << (descriptor.buildTag ? descriptor.buildTag : "(none)")
               << "', the engine with '" << GS_MODULE_BUILD_TAG << "'";
    } else if (!descriptor.name || expectedName != descriptor.name) {
        reason << "library calls itself '" << (descriptor.name ? descriptor.name : "(none)") << "'";
    } else if (!descriptor.create || !descriptor.destroy) {
        reason << "descriptor lacks a create or destroy function";
    }
    return reason.str();
}

LoadedModule::LoadedModule(void* library, const ModuleDescriptor& descriptor, std::filesystem::path path)
    : library_(library), descriptor_(descriptor), path_(std::move(path)), module_(descriptor.create()) {
    if (!module_) {
        dlclose(library_);
        throw ModuleError("module '" + std::string(descriptor.name) + "' (" + path_.string() +
                          "): its factory returned no module");
    }
}

LoadedModule::~LoadedModule() {
    descriptor_.destroy(module_);
    dlclose(library_);
}

void* LoadedModule::symbol(const char* name) const {
    return dlsym(library_, name);
}

ModuleLoader::ModuleLoader() = default;

void ModuleLoader::addSearchPath(std::filesystem::path folder) {
    extraPaths_.push_back(std::move(folder));
}

std::string ModuleLoader::fileNameFor(std::string_view moduleName) {
    return "libgs_module_" + std::string(moduleName) + ".so";
}

std::vector<std::filesystem::path> ModuleLoader::searchPaths() const {
    std::vector<std::filesystem::path> paths = extraPaths_;
    if (const char* variable = std::getenv("GS_MODULE_PATH")) {
        std::istringstream list(variable);
        for (std::string folder; std::getline(list, folder, ':');) {
            if (!folder.empty()) {
                paths.emplace_back(folder);
            }
        }
    }
    if (const auto folder = executableFolder(); !folder.empty()) {
        paths.push_back(folder);
        paths.push_back(folder.parent_path() / "lib"); // the build tree's bin/ and lib/
        // An installed executable's prefix, when its library folder is not lib/ (e.g. lib/x86_64-linux-gnu).
        if (const auto installed = (folder / GS_MODULE_DIR_FROM_BINDIR).lexically_normal();
            installed != paths.back().lexically_normal()) {
            paths.push_back(installed);
        }
    }
    return paths;
}

std::unique_ptr<LoadedModule> ModuleLoader::load(std::string_view name) const {
    const std::string quoted = "module '" + std::string(name) + "'";
    if (!isValidModuleName(name)) {
        throw ModuleError(quoted + ": a module name uses only a-z, 0-9, '_' and '-' (at most 64 characters)");
    }
    const std::string fileName = fileNameFor(name);
    std::filesystem::path found;
    std::string searched;
    for (const auto& folder : searchPaths()) {
        std::error_code error;
        if (std::filesystem::is_regular_file(folder / fileName, error)) {
            found = folder / fileName;
            break;
        }
        searched += "\n  " + folder.string();
    }
    if (found.empty()) {
        throw ModuleError(quoted + " not found: no " + fileName + " in" + searched +
                          "\n(set GS_MODULE_PATH to the folder that holds it)");
    }
    void* library = dlopen(found.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        throw ModuleError(quoted + " (" + found.string() + ") cannot be loaded: " + dlerror());
    }
    using DescriptorFunction = const ModuleDescriptor* (*)();
    auto entry = reinterpret_cast<DescriptorFunction>(dlsym(library, "gsModuleDescriptor"));
    const ModuleDescriptor* descriptor = entry ? entry() : nullptr;
    if (!descriptor) {
        dlclose(library);
        throw ModuleError(
            quoted + " (" + found.string() +
            ") is not an engine module: it exports no gsModuleDescriptor (use GS_EXPORT_MODULE)");
    }
    if (const std::string reason = checkModuleDescriptor(*descriptor, name); !reason.empty()) {
        dlclose(library);
        throw ModuleError(quoted + " (" + found.string() + ") is incompatible: " + reason);
    }
    return std::make_unique<LoadedModule>(library, *descriptor, found);
}

} // namespace engine

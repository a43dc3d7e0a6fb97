#pragma once

// Sections of the docs generated from code: between `<!-- generated: NAME -->` and `<!-- end: NAME -->`.
// When one drifts, the test writes the expected document next to the build and says how to take it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

/// `document` is relative to the source folder, e.g. "docs/SHADOWS.md".
inline void expectGeneratedSection(const std::string& document, const std::string& name,
                                   const std::string& expected) {
    const std::filesystem::path path = std::filesystem::path(SOURCE_DIR) / document;
    std::ifstream file(path);
    ASSERT_TRUE(file) << path;
    std::stringstream text;
    text << file.rdbuf();
    std::string content = text.str();
    const std::string begin = "<!-- generated: " + name + " -->\n";
    const std::string end = "<!-- end: " + name + " -->";
    const std::size_t from = content.find(begin);
    const std::size_t to = content.find(end);
    ASSERT_NE(from, std::string::npos) << path << " lacks " << begin;
    ASSERT_NE(to, std::string::npos) << path << " lacks " << end;
    const std::string actual = content.substr(from + begin.size(), to - from - begin.size());
    if (actual != expected) {
        content.replace(from + begin.size(), actual.size(), expected);
        const std::filesystem::path fixed = std::filesystem::current_path() / path.filename();
        std::ofstream(fixed) << content;
        ADD_FAILURE() << path << ": the '" << name << "' section is out of date; the generated document is "
                      << fixed << " (cp it over the original)";
    }
}

#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace shadows {

/// @brief One value of an enum and its stable name in settings files, command lines and docs.
template <typename Enum>
struct EnumName {
    /// The enumerator.
    Enum value;
    /// Its name, e.g. "pcf-gsm-quadratic".
    std::string_view name;
};

/// @brief The one name table of `Enum`, in declaration order. Specialised next to each settings enum.
template <typename Enum>
std::span<const EnumName<Enum>> enumNames();

/// @brief The name of `value`, "?" for a value outside the table.
template <typename Enum>
std::string_view nameOf(Enum value) {
    for (const EnumName<Enum>& entry : enumNames<Enum>()) {
        if (entry.value == value) {
            return entry.name;
        }
    }
    return "?";
}

template <typename Enum>
std::optional<Enum> enumFromName(std::string_view name) {
    for (const EnumName<Enum>& entry : enumNames<Enum>()) {
        if (entry.name == name) {
            return entry.value;
        }
    }
    return std::nullopt;
}

/// @brief Every name of `Enum` joined by `separator`, for messages and usage texts.
template <typename Enum>
std::string nameList(std::string_view separator = ", ") {
    std::string list;
    for (const EnumName<Enum>& entry : enumNames<Enum>()) {
        list += (list.empty() ? "" : std::string(separator)) + std::string(entry.name);
    }
    return list;
}

} // namespace shadows

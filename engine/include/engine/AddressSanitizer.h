#pragma once

/// @file
/// @brief GS_ADDRESS_SANITIZER is defined where AddressSanitizer instruments the build. GCC says so with
/// __SANITIZE_ADDRESS__, Clang (14 at least) only through __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define GS_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GS_ADDRESS_SANITIZER 1
#endif
#endif

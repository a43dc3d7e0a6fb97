#pragma once

#include <engine/HeadlessContext.h>

#include <memory>

/// @brief One EGL surfaceless context for the whole test process, made current on first use.
inline engine::HeadlessContext& glTestContext() {
    static engine::HeadlessContext context;
    context.makeCurrent();
    return context;
}

#pragma once

#include <engine/gl/GlObject.h>

#include <array>
#include <chrono>
#include <string_view>

namespace engine {

class GlContext;

/// @brief How GPU work is timed.
enum class TimingMethod {
    /// glFinish, then a steady clock: the only honest method on software renderers, whose timer queries
    /// time command submission only.
    FinishAndSteadyClock,
    /// GL_TIMESTAMP queries around the work (GPU time), read back synchronously.
    TimerQuery,
};

/// @brief Times one stretch of GL work at a time: begin(), submit the work, end() returns milliseconds.
class PassTimer {
public:
    explicit PassTimer(TimingMethod method);

    /// @brief The right method for `context`: FinishAndSteadyClock on software renderers, TimerQuery
    /// otherwise.
    static TimingMethod methodFor(const GlContext& context);
    /// @brief Human-readable name of a method, recorded beside every figure.
    static std::string_view describe(TimingMethod method);

    void begin();
    /// @brief Milliseconds since begin(), waiting for the GPU to finish the work.
    double end();

    [[nodiscard]] TimingMethod method() const { return method_; }

private:
    TimingMethod method_;
    std::chrono::steady_clock::time_point start_;
    /// Start and end timestamps, created on first use and deleted with the timer.
    std::array<gl::GlObject<gl::detail::deleteQuery>, 2> queries_;
};

} // namespace engine

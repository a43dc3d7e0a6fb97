#include <engine/GlContext.h>
#include <engine/PassTimer.h>

namespace engine {

PassTimer::PassTimer(TimingMethod method) : method_(method) {}

TimingMethod PassTimer::methodFor(const GlContext& context) {
    return context.isSoftwareRenderer() ? TimingMethod::FinishAndSteadyClock : TimingMethod::TimerQuery;
}

std::string_view PassTimer::describe(TimingMethod method) {
    return method == TimingMethod::FinishAndSteadyClock ? "glFinish + steady_clock (CPU wall time)"
                                                        : "GL_TIMESTAMP queries (GPU time)";
}

void PassTimer::begin() {
    if (method_ == TimingMethod::FinishAndSteadyClock) {
        glFinish();
        start_ = std::chrono::steady_clock::now();
        return;
    }
    if (!queries_[0]) {
        for (auto& query : queries_) {
            GLuint name = 0;
            glCreateQueries(GL_TIMESTAMP, 1, &name);
            query = gl::GlObject<gl::detail::deleteQuery>(name);
        }
    }
    glQueryCounter(queries_[0].id(), GL_TIMESTAMP);
}

double PassTimer::end() {
    if (method_ == TimingMethod::FinishAndSteadyClock) {
        glFinish();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }
    glQueryCounter(queries_[1].id(), GL_TIMESTAMP);
    GLuint64 start = 0;
    GLuint64 stop = 0;
    glGetQueryObjectui64v(queries_[0].id(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(queries_[1].id(), GL_QUERY_RESULT, &stop);
    return static_cast<double>(stop - start) * 1e-6;
}

} // namespace engine

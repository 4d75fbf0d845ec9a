#include "motion_evaluation.hpp"

#include "scene/motion_steps.hpp"

#include <fmt/format.h>

#include <ostream>

namespace crt::lang {

namespace {

/// Where in `c`'s sources a span of the scene is (the start of the file when unknown).
SourceRange rangeOf(const Compilation& c, const scene::SourceSpan& span) {
    if (span.line == 0 || span.file >= c.sources.fileCount()) return {0, 0, 0};
    const SourceFile& file = c.sources.file(span.file);
    const uint32_t begin = file.offsetOf(LineColumn{span.line, span.column});
    const uint32_t end = span.endLine > 0 ? file.offsetOf(LineColumn{span.endLine, span.endColumn}) : begin;
    return {span.file, begin, std::max(begin, end)};
}

} // namespace

void evaluateMotionSteps(Compilation& c, const EvalOptions& options) {
    if (!c.scene || options.motionStep || !c.scene->settings.shutterIsOpen()) return;
    const scene::SettingsDesc& settings = c.scene->settings;
    const SourceFile& main = c.sources.file(0);
    std::ostream discard(nullptr); // print() has spoken once, in the frame's own evaluation
    std::vector<scene::SceneDesc> steps;
    for (int k = 0; k < settings.motionSteps; ++k) {
        EvalOptions at = options;
        at.motionStep = settings.shutterOpen + scene::motionStepFraction(k, settings.motionSteps) *
                                                   (settings.shutterClose - settings.shutterOpen);
        at.printOut = &discard;
        at.keepGlobalValues = false;
        Compilation step = compile(main.path(), std::string(main.text()), at);
        if (!step.scene) {
            for (Diagnostic& d : step.diagnostics.items()) {
                if (d.severity != Severity::Error) continue;
                d.message = fmt::format("at the motion step t = {}: {}",
                                        (options.time ? *options.time : options.frame) + *at.motionStep, d.message);
                c.diagnostics.add(std::move(d));
            }
            c.scene.reset();
            return;
        }
        steps.push_back(std::move(*step.scene));
    }
    if (std::optional<scene::MotionConflict> conflict = scene::joinMotionSteps(*c.scene, steps)) {
        c.diagnostics.error(rangeOf(c, conflict->where), conflict->message);
        c.scene.reset();
    }
}

} // namespace crt::lang

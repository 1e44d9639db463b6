#include "g2d/derive_grammar.hpp"

#include "g2d/drawn_faces.hpp"
#include "g2d/edge_bends.hpp"
#include "g2d/source_excerpt.hpp"

namespace g2d::rt {

std::string renderLocatedError(const SourceLocation& at, const std::string& message) {
    std::string out = at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.col) + ": error: " + message + "\n";
    if (at.line == 0) return out;
    const Excerpt ex = excerptLine(at.lineText, at.col, at.endCol);
    return out + "  " + ex.line + "\n  " + std::string(ex.pad, ' ') + "^" + std::string(ex.width - 1, '~') + "\n";
}

void deriveGrammar(GrammarRun& grammar, const std::vector<Value>& params, std::uint64_t seed, const RunSettings& settings,
                   DerivedRun& out, const StepObserver& observer, RunProgress* progress, StepTracer* tracer) {
    out = DerivedRun{};
    Rng rng(seed);
    grammar.start(params, rng);
    if (tracer) tracer->started();
    if (progress) *progress = RunProgress{true, 0};
    DerivationOptions options;
    const std::optional<long long> grammarLimit = grammar.stepLimit();
    out.canvas = grammar.canvas();   // checked even when --viewbox overrides it, as the limit is
    options.steps = settings.steps ? settings.steps : grammarLimit ? grammarLimit : kDefaultStepLimit;
    options.perPriority = grammar.priorityLimits();
    options.perRule = grammar.ruleLimits();
    options.repeatCounts = grammar.repeatCounts();
    options.maxElements = settings.maxElements;
    options.timeoutSeconds = settings.timeoutSeconds;
    options.verifyMatches = settings.verifyMatches;
    options.wholeDrawings = settings.wholeDrawings;
    options.drawingCanvas = out.canvas;
    derive(
        grammar.graph(), grammar.rules(), rng, options, out.result,
        [&](long long s, const Graph& g) {
            if (progress) progress->step = s;
            if (observer) observer(s, g);
        },
        tracer);
    if (const AngleLayoutSpec* layout = grammar.rules().angleLayout()) {
        addDrawnFaces(grammar.graph(), grammar.rules(), *layout, out.result.steps);
        out.result.bendsReduced = bendEdges(grammar.graph(), *layout, rng).reduced;
    }
    out.hitDefaultLimit = out.result.stopped == StopReason::StepLimit && !settings.steps && !grammarLimit;
}

}  // namespace g2d::rt

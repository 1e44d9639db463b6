#include "driver/run_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

#include "driver/compile.hpp"
#include "g2d/run_driver.hpp"
#include "interp/interpreted_run.hpp"

namespace g2d {

int runRun(const RunOptions& options) {
    CompileResult compiled = compileAndReport(options.file);
    if (!compiled.program) return 1;

    rt::RunRequest request;
    request.grammarFile = options.file;
    request.svgOut = options.svgOut;
    request.jsonOut = options.jsonOut;
    request.noSvg = options.noSvg;
    request.seed = options.seed;
    request.defines = options.defines;
    request.steps = options.steps;
    request.stats = options.stats;
    request.maxElements = options.maxElements;
    request.timeoutSeconds = options.timeoutSeconds;
    request.keepPartial = options.keepPartial;
    request.traceHtml = options.traceHtml;
    request.traceJson = options.traceJson;
    interp::InterpretedRun grammar(*compiled.program, &compiled.sources);
    return rt::runGrammar(request, grammar);
}

}  // namespace g2d

#include "driver/run_command.hpp"

#include <cstdio>

#include "front/compile.hpp"
#include "g2d/run_options.hpp"
#include "interp/interpreted_run.hpp"

namespace g2d {

int runRun(const rt::RunRequest& request) {
    CompileResult compiled = compileAndReport(request.grammarFile);
    if (!compiled.program) return 1;
    interp::InterpretedRun grammar(*compiled.program, &compiled.sources);
    return rt::runGrammar(request, grammar);
}

int printGrammarParameters(const std::string& file) {
    CompileResult compiled = compileAndReport(file);
    if (!compiled.program) return 1;
    interp::InterpretedRun grammar(*compiled.program, &compiled.sources);
    std::printf("\n%s", rt::parameterHelp(grammar.params()).c_str());
    return 0;
}

}  // namespace g2d

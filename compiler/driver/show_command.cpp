#include "driver/show_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "front/compile.hpp"
#include "g2d/atomic_file.hpp"
#include "show/production_diagram.hpp"

namespace g2d {

int runShow(const ShowOptions& options) {
    CompileResult compiled = compileAndReport(options.file);
    if (!compiled.program) return 1;
    const std::string title = std::filesystem::path(options.file).filename().string();
    const bool svg = std::filesystem::path(options.output).extension() == ".svg";
    try {
        rt::AtomicFile out(options.output);
        out.commit(svg ? show::productionsSvg(*compiled.program, compiled.sources, title)
                       : show::productionsPage(*compiled.program, compiled.sources, title));
    } catch (const rt::OutputError& e) {
        std::fprintf(stderr, "g2d show: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace g2d

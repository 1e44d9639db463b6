#include "driver/check_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

#include "front/compile.hpp"

namespace g2d {

int runCheck(const std::vector<std::string>& files, DiagnosticsFormat format, bool werror) {
    const bool color = format == DiagnosticsFormat::Text && isatty(STDERR_FILENO) && !std::getenv("NO_COLOR");
    LoadOptions options;
    options.importDirs = defaultImportDirs();
    bool failed = false;
    std::string json = "[";
    for (const auto& file : files) {
        CompileResult r = compileFile(file, options);
        const auto sorted = r.diags.sorted();
        for (const auto& d : sorted) {
            if (d.severity == Severity::Error) failed = true;
            if (d.severity == Severity::Warning && werror) failed = true;
        }
        if (format == DiagnosticsFormat::Text) {
            for (const auto& d : sorted) std::fputs(renderText(d, r.sources, color).c_str(), stderr);
        } else {
            std::string part = renderJson(sorted, r.sources);
            part = part.substr(1, part.size() - 2);  // strip [ ]
            if (!part.empty()) json += (json.size() > 1 ? "," : "") + part;
        }
    }
    if (format == DiagnosticsFormat::Json) std::printf("%s]\n", json.c_str());
    return failed ? 1 : 0;
}

}  // namespace g2d

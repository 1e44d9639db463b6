#include <charconv>
#include <cstdio>
#include <cstring>

#include "g2d/run_driver.hpp"

namespace g2d::rt {

namespace {

void usage(FILE* to, const char* program) {
    std::fprintf(to,
                 "usage: %s [-o OUT.svg] [--json OUT.json] [--no-svg] [--seed N] [-D NAME=VALUE]... [--steps N] "
                 "[--stats] [--max-elements N] [--timeout SECONDS] [--keep-partial] [--trace OUT.html] [--trace-json OUT.json]\n"
                 "  -o, --output FILE   SVG output (default: the grammar's name with .svg)\n"
                 "  --json FILE         the graph in NetworkX node-link JSON\n"
                 "  --no-svg            write no SVG\n"
                 "  --seed N            seed of the random generator (default 1)\n"
                 "  -D NAME=VALUE       set a parameter\n"
                 "  --steps N           global step limit (overrides the grammar's)\n"
                 "  --stats             print one JSON line of statistics on stdout\n"
                 "  --max-elements N    stop with an error past N nodes + edges (default 10000000)\n"
                 "  --timeout SECONDS   stop with an error when the derivation runs longer\n"
                 "  --keep-partial      after an error or a bound, still write the last completed step\n"
                 "  --trace FILE        the derivation step by step, as a self-contained HTML page\n"
                 "  --trace-json FILE   the same trace, as JSON\n",
                 program);
}

template <class T>
bool parseNumber(const char* text, T& out) {
    const char* end = text + std::strlen(text);
    auto res = std::from_chars(text, end, out);
    return res.ec == std::errc() && res.ptr == end && end != text;
}

}  // namespace

std::optional<int> parseRunArguments(int argc, char** argv, const std::string& grammarFile, RunRequest& out) {
    out.grammarFile = grammarFile;
    const char* program = argc > 0 ? argv[0] : "grammar";
    auto fail = [&](const std::string& message) -> std::optional<int> {
        std::fprintf(stderr, "%s: error: %s\n", program, message.c_str());
        usage(stderr, program);
        return 2;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](const char* what) -> const char* {
            if (i + 1 >= argc) return nullptr;
            (void)what;
            return argv[++i];
        };
        if (a == "-h" || a == "--help") {
            usage(stdout, program);
            return 0;
        } else if (a == "-o" || a == "--output") {
            const char* v = value("FILE");
            if (!v) return fail(a + " needs a file");
            out.svgOut = v;
        } else if (a == "--json") {
            const char* v = value("FILE");
            if (!v) return fail("--json needs a file");
            out.jsonOut = v;
        } else if (a == "--no-svg") {
            out.noSvg = true;
        } else if (a == "--stats") {
            out.stats = true;
        } else if (a == "--seed") {
            const char* v = value("N");
            if (!v || !parseNumber(v, out.seed)) return fail("--seed needs a non-negative integer");
        } else if (a == "--steps") {
            const char* v = value("N");
            long long n = 0;
            if (!v || !parseNumber(v, n)) return fail("--steps needs an integer");
            out.steps = n;
        } else if (a == "--max-elements") {
            const char* v = value("N");
            long long n = 0;
            if (!v || !parseNumber(v, n)) return fail("--max-elements needs an integer");
            out.maxElements = n;
        } else if (a == "--timeout") {
            const char* v = value("SECONDS");
            double t = 0;
            if (!v || !parseNumber(v, t)) return fail("--timeout needs a number of seconds");
            out.timeoutSeconds = t;
        } else if (a == "--trace" || a == "--trace-json") {
            const char* v = value("FILE");
            if (!v) return fail(a + " needs a file");
            (a == "--trace" ? out.traceHtml : out.traceJson) = v;
        } else if (a == "--keep-partial") {
            out.keepPartial = true;
        } else if (a == "-D" || a == "--define") {
            const char* v = value("NAME=VALUE");
            if (!v) return fail("-D needs NAME=VALUE");
            out.defines.push_back(v);
        } else if (a.rfind("-D", 0) == 0 && a.size() > 2) {
            out.defines.push_back(a.substr(2));
        } else {
            return fail("unknown argument `" + a + "`");
        }
    }
    return std::nullopt;
}

}  // namespace g2d::rt

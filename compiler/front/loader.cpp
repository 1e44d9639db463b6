#include "front/loader.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

#include "parse/parser.hpp"

namespace g2d {

namespace fs = std::filesystem;

std::vector<std::string> defaultImportDirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("G2D_STDLIB"); env && *env) dirs.push_back(env);
#ifdef G2D_STDLIB_DIR
    dirs.push_back(G2D_STDLIB_DIR);
#endif
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) dirs.push_back((exe.parent_path().parent_path() / "share" / "g2d" / "stdlib").string());
    return dirs;
}

namespace {

struct Loader {
    const LoadOptions& options;
    SourceManager& sm;
    Diagnostics& diags;
    std::vector<ast::Program>& out;
    std::map<std::string, int> state;   // canonical path -> 1 loading, 2 done
    std::vector<std::pair<std::string, Span>> stack;  // for cycle messages

    // Reads a file; on failure reports at `from` (an import) or as a file-level error.
    std::optional<std::string> read(const std::string& display, const fs::path& p, Span from) {
        auto fail = [&](const std::string& why) {
            if (from.valid()) diags.error(from, why);
            else {
                FileId id = sm.add(display, "");
                diags.error(Span{id, 0, 0, 0, 0}, why);
            }
            return std::nullopt;
        };
        std::error_code ec;
        auto status = fs::status(p, ec);
        // (A symbolic-link loop or a folder we may not enter is not "no such file".)
        if (ec && ec != std::errc::no_such_file_or_directory)
            return fail("cannot open `" + display + "`: " + ec.message());
        if (ec || !fs::exists(status)) return fail("cannot open `" + display + "`: no such file");
        if (fs::is_directory(status)) return fail("cannot read `" + display + "`: it is a directory, not a .g2d file");
        if (!fs::is_regular_file(status)) return fail("cannot read `" + display + "`: not a regular file");
        auto size = fs::file_size(p, ec);
        if (!ec && size > options.maxFileBytes)
            return fail("`" + display + "` is too large (" + std::to_string(size) + " bytes; the limit is " +
                        std::to_string(options.maxFileBytes) + ")");
        std::ifstream in(p, std::ios::binary);
        if (!in) return fail("cannot open `" + display + "`: " + std::strerror(errno));
        std::ostringstream ss;
        ss << in.rdbuf();
        if (in.bad()) return fail("cannot read `" + display + "`: " + std::strerror(errno));
        return ss.str();
    }

    bool load(const std::string& display, const fs::path& path, Span from) {
        std::error_code ec;
        fs::path canonical = fs::weakly_canonical(path, ec);
        const std::string key = ec ? path.string() : canonical.string();
        if (auto it = state.find(key); it != state.end()) {
            if (it->second == 2) return true;
            std::string chain;
            bool inCycle = false;
            for (const auto& [p, s] : stack) {
                if (p == key) inCycle = true;
                if (inCycle) chain += "`" + fs::path(p).filename().string() + "` → ";
            }
            chain += "`" + fs::path(key).filename().string() + "`";
            diags.error(from, "import cycle: " + chain);
            return false;
        }
        auto text = read(display, path, from);
        if (!text) return false;
        state[key] = 1;
        FileId id = sm.add(display, std::move(*text));
        auto program = parseFile(sm, id, diags);
        if (!program) { state[key] = 2; return false; }
        bool ok = true;
        stack.emplace_back(key, from);
        for (const auto& d : program->decls) {
            const auto* imp = std::get_if<ast::ImportDecl>(&d.decl);
            if (!imp) continue;
            auto found = resolveImport(imp->path, path.parent_path().string(), options);
            std::optional<fs::path> resolved;
            if (found) resolved = fs::path(*found);
            if (!resolved) {
                diags.error(imp->span, "cannot find imported file `" + imp->path + "`" +
                                           (fs::path(imp->path).is_absolute()
                                                ? std::string()
                                                : " (looked next to the importing file and in the standard library)"));
                ok = false;
                continue;
            }
            std::string shown = resolved->lexically_normal().string();
            ok = load(shown, *resolved, imp->span) && ok;
        }
        stack.pop_back();
        state[key] = 2;
        out.push_back(std::move(*program));
        return ok;
    }
};

}  // namespace

std::optional<std::string> resolveImport(const std::string& name, const std::string& fromDir,
                                         const LoadOptions& options) {
    std::vector<fs::path> candidates;
    const fs::path rel(name);
    if (rel.is_absolute()) {
        candidates.push_back(rel);
    } else {
        candidates.push_back(fs::path(fromDir) / rel);
        for (const auto& d : options.importDirs) candidates.push_back(fs::path(d) / rel);
    }
    for (const auto& c : candidates) {
        std::error_code ec;
        // A symbolic link counts even when it leads nowhere: reading it then
        // says why (a loop, a dangling link), not "cannot find".
        if (fs::exists(fs::symlink_status(c, ec))) return c.string();
    }
    return std::nullopt;
}

bool loadGrammar(const std::string& path, const LoadOptions& options, SourceManager& sm, Diagnostics& diags,
                 std::vector<ast::Program>& out) {
    Loader loader{options, sm, diags, out, {}, {}};
    return loader.load(path, fs::path(path), Span{}) && !diags.hasErrors();
}

}  // namespace g2d

#include "driver/build_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

#include "front/compile.hpp"
#include "emit/cpp_emitter.hpp"
#include "g2d/atomic_file.hpp"

namespace g2d {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> emitFor(const std::string& file, bool withMain = true,
                                   const std::string& factory = "g2d_make_grammar") {
    CompileResult compiled = compileAndReport(file);
    if (!compiled.program) return std::nullopt;
    emit::EmitOptions options;
    options.grammarFile = file;
    options.sources = &compiled.sources;
    options.withMain = withMain;
    options.factoryName = factory;
    return emit::emitCpp(*compiled.program, options);
}

int fail(const std::string& message) {
    std::fprintf(stderr, "g2d build: error: %s\n", message.c_str());
    return 1;
}

// Where the runtime's headers and libraries are: next to an installed g2d
// (PREFIX/bin/g2d → PREFIX/include, PREFIX/lib), else the build tree. A
// program with a main links g2d_run, then the g2d_engine it builds on.
struct RuntimePaths {
    std::vector<std::string> includes, libraries;
};

std::optional<RuntimePaths> findRuntime() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path prefix = exe.parent_path().parent_path();
        for (const char* lib : {"lib", "lib64"}) {
            const fs::path run = prefix / lib / "libg2d_run.a", engine = prefix / lib / "libg2d_engine.a";
            if (fs::exists(prefix / "include/g2d/compiled.hpp", ec) && fs::exists(run, ec) && fs::exists(engine, ec))
                return RuntimePaths{{(prefix / "include").string()}, {run.string(), engine.string()}};
        }
    }
#if defined(G2D_BUILD_ENGINE_INCLUDE) && defined(G2D_BUILD_RUN_INCLUDE) && defined(G2D_BUILD_ENGINE_LIB) && \
    defined(G2D_BUILD_RUN_LIB)
    if (fs::exists(G2D_BUILD_RUN_LIB, ec) && fs::exists(G2D_BUILD_ENGINE_LIB, ec))
        return RuntimePaths{{G2D_BUILD_ENGINE_INCLUDE, G2D_BUILD_RUN_INCLUDE}, {G2D_BUILD_RUN_LIB, G2D_BUILD_ENGINE_LIB}};
#endif
    return std::nullopt;
}

std::optional<std::string> findProgram(const std::string& name) {
    if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? std::optional(name) : std::nullopt;
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = dirs.find(':', start);
        const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return std::nullopt;
}

// Runs a command (no shell), its output passing through. Returns its exit status.
int runCommand(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

#if defined(G2D_RUNTIME_LINK_FLAGS) || defined(G2D_RUNTIME_LIBS)
std::vector<std::string> splitFlags(const std::string& flags) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < flags.size()) {
        const std::size_t j = flags.find(' ', i);
        const std::string f = flags.substr(i, j == std::string::npos ? std::string::npos : j - i);
        if (!f.empty()) out.push_back(f);
        if (j == std::string::npos) break;
        i = j + 1;
    }
    return out;
}
#endif

}  // namespace

int runEmitCpp(const BuildOptions& options) {
    auto code = emitFor(options.file, options.withMain, options.factory);
    if (!code) return 1;
    try {
        rt::AtomicFile out(options.output);
        out.commit(*code);
    } catch (const rt::OutputError& e) {
        return fail(e.what());
    }
    return 0;
}

int runBuild(const BuildOptions& options) {
    const std::string level = options.optimize;
    if (level != "0" && level != "1" && level != "2" && level != "3" && level != "s" && level != "g") {
        std::fprintf(stderr, "g2d build: error: -O takes 0, 1, 2, 3, s or g\n");
        return 2;  // a usage error
    }
    auto code = emitFor(options.file);
    if (!code) return 1;
    const auto runtime = findRuntime();
    if (!runtime) return fail("cannot find the g2d runtime (include/g2d, lib/libg2d_run.a and lib/libg2d_engine.a next to g2d, or the build tree)");
    const char* envCxx = std::getenv("CXX");
    const std::string cxxName = options.cxx.value_or(envCxx && *envCxx ? envCxx : "c++");
    const auto cxx = findProgram(cxxName);
    if (!cxx) return fail("no C++ compiler `" + cxxName + "` found; install g++ (apt-get install g++) or pass --cxx COMPILER");

    // The generated source: kept where asked, else in a temporary folder.
    std::error_code ec;
    fs::path workDir = fs::temp_directory_path(ec) / ("g2d-build-" + std::to_string(getpid()));
    fs::create_directories(workDir, ec);
    const fs::path cpp = options.keepCpp ? fs::path(*options.keepCpp) : workDir / (fs::path(options.file).stem().string() + ".cpp");
    try {
        rt::AtomicFile out(cpp.string());
        out.commit(*code);
    } catch (const rt::OutputError& e) {
        fs::remove_all(workDir, ec);
        return fail(e.what());
    }
    // The executable appears whole: compiled next to the target, then renamed.
    const fs::path target(options.output);
    if (fs::is_directory(target, ec)) {
        fs::remove_all(workDir, ec);
        return fail("cannot write `" + options.output + "`: it is a directory");
    }
    const fs::path temp = target.string() + ".tmp-" + std::to_string(getpid());
    std::vector<std::string> args = {*cxx, "-std=c++20", "-O" + level, "-ffp-contract=off"};
    for (const auto& dir : runtime->includes) args.insert(args.end(), {"-I", dir});
    args.push_back(cpp.string());
    args.insert(args.end(), runtime->libraries.begin(), runtime->libraries.end());
    args.insert(args.end(), {"-o", temp.string()});
#ifdef G2D_RUNTIME_LIBS
    // The runtime's own libraries (librsvg and cairo: PNG output), after it.
    for (const auto& f : splitFlags(G2D_RUNTIME_LIBS)) args.insert(args.end() - 2, f);
#endif
#ifdef G2D_RUNTIME_LINK_FLAGS
    for (const auto& f : splitFlags(G2D_RUNTIME_LINK_FLAGS)) args.insert(args.begin() + 1, f);
#endif
    if (options.verbose) {
        std::string line;
        for (const auto& a : args) line += a + " ";
        std::fprintf(stderr, "%s\n", line.c_str());
    }
    const int status = runCommand(args);
    if (status != 0) {
        fs::remove(temp, ec);
        // Keep the source for inspection.
        fs::path kept = cpp;
        if (!options.keepCpp) {
            kept = fs::path(options.output).string() + ".cpp";
            fs::copy_file(cpp, kept, fs::copy_options::overwrite_existing, ec);
            if (ec) kept = cpp;
        }
        if (!options.keepCpp) fs::remove_all(workDir, ec);
        return fail("the C++ compiler failed (" + *cxx + ", exit status " + std::to_string(status) +
                    "); the generated code is kept at `" + kept.string() + "`");
    }
    fs::rename(temp, target, ec);
    if (ec) {
        fs::remove(temp, ec);
        fs::remove_all(workDir, ec);
        return fail("cannot write `" + options.output + "`: " + ec.message());
    }
    fs::remove_all(workDir, ec);
    return 0;
}

}  // namespace g2d

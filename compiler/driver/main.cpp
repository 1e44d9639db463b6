// g2d: graph grammars that generate 2D shapes.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "driver/check_command.hpp"

int main(int argc, char** argv) {
    CLI::App app{"g2d: a compiled language for graph grammars that generate 2D shapes"};
    app.set_version_flag("--version", "g2d 0.1.0");
    app.require_subcommand(1);

    auto* check = app.add_subcommand("check", "Check grammar files and report every error");
    std::vector<std::string> checkFiles;
    std::string format = "text";
    bool werror = false;
    check->add_option("FILE", checkFiles, ".g2d files to check")->required();
    check->add_option("--diagnostics-format", format, "text (default) or json")
        ->check(CLI::IsMember({"text", "json"}));
    check->add_flag("--werror", werror, "Treat warnings as errors");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;  // usage error
    }

    if (check->parsed()) {
        return g2d::runCheck(checkFiles,
                             format == "json" ? g2d::DiagnosticsFormat::Json : g2d::DiagnosticsFormat::Text,
                             werror);
    }
    return 2;
}

#include "driver/import_command.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "front/reserved_names.hpp"
#include "g2d/atomic_file.hpp"
#include "import/model_gen_grammar.hpp"
#include "import/model_gen_import.hpp"

namespace g2d {

int runImport(const ImportCommandOptions& options) {
    std::ifstream in(options.input, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "g2d import: error: cannot read %s\n", options.input.c_str());
        return 1;
    }
    std::stringstream text;
    text << in.rdbuf();
    import::ImportedGrammar imported;
    try {
        const std::string name = options.input.substr(options.input.find_last_of('/') + 1);
        imported = import::importModelGen(import::readModelGenGrammar(text.str()), name,
                                          {front::reservedNames(), front::attributeNamesRefused(), front::keywordNames()});
    } catch (const import::MgError& e) {
        std::fprintf(stderr, "%s:%d: error: %s\n", options.input.c_str(), e.line, e.what());
        return 1;
    }
    if (!options.quiet)
        for (const auto& w : imported.warnings) {
            if (w.line > 0) std::fprintf(stderr, "%s:%d: warning: %s\n", options.input.c_str(), w.line, w.message.c_str());
            else std::fprintf(stderr, "%s: warning: %s\n", options.input.c_str(), w.message.c_str());
        }
    if (options.output.empty()) {
        std::fwrite(imported.source.data(), 1, imported.source.size(), stdout);
        return 0;
    }
    try {
        rt::AtomicFile file(options.output);
        file.commit(imported.source);
    } catch (const rt::OutputError& e) {
        std::fprintf(stderr, "g2d import: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace g2d

#pragma once
// `g2d lsp`: a Language Server Protocol server over stdio, on the compiler's
// own front end. Diagnostics on open and change (the messages of
// `g2d check`), hover (what a name is and the line that declares it, the
// signature of a built-in), go to definition (kinds, attributes,
// productions, functions, parameters, constants, enums, matched and daughter
// elements, `let` bindings, imported files), document symbols, and
// completion of names, attributes after `.`, built-ins and keywords.
#include <iosfwd>

namespace g2d::lsp {

// Serves until `exit` or the end of the input; returns the exit code (0
// after `shutdown` then `exit`, 1 otherwise, as the protocol asks).
int runLanguageServer(std::istream& in, std::ostream& out);

}  // namespace g2d::lsp

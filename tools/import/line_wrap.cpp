#include "import/line_wrap.hpp"

#include <vector>

namespace g2d::import {

namespace {

struct Separator {
    std::size_t at;      // where it starts
    std::size_t length;
    int depth;           // of brackets around it
    bool before;         // ` and ` starts the next piece; `, ` ends this one
};

// The separators of `code` (no strings are cut), and where a trailing `//` comment starts (npos: none).
std::vector<Separator> separators(const std::string& code, std::size_t& comment) {
    std::vector<Separator> out;
    comment = std::string::npos;
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') inString = true;
        else if (c == '(' || c == '{' || c == '[') ++depth;
        else if (c == ')' || c == '}' || c == ']') --depth;
        else if (c == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            comment = i;
            break;
        } else if (c == ',' && i + 1 < code.size() && code[i + 1] == ' ') {
            out.push_back({i, 2, depth, false});
        } else if (c == ' ' && code.compare(i, 5, " and ") == 0) {
            out.push_back({i, 5, depth, true});
        }
    }
    return out;
}

std::string rtrim(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

// `indent` for the first line, `more` for the lines that continue it.
void wrap(const std::string& indent, const std::string& more, const std::string& code, std::size_t width, std::string& out) {
    std::size_t comment = 0;
    const std::vector<Separator> seps = separators(code, comment);
    if (comment != std::string::npos && indent.size() + code.size() > width) {   // the comment above
        out += indent + code.substr(comment) + "\n";
        return wrap(indent, more, rtrim(code.substr(0, comment)), width, out);
    }
    if (indent.size() + code.size() <= width || seps.empty()) {
        out += indent + code + "\n";
        return;
    }
    int shallowest = seps[0].depth;
    for (const Separator& s : seps) shallowest = std::min(shallowest, s.depth);
    std::vector<std::string> pieces;
    std::size_t from = 0;
    for (const Separator& s : seps) {
        if (s.depth != shallowest) continue;
        const std::size_t cut = s.before ? s.at + 1 : s.at + s.length - 1;   // ` and x`: cut before `and`; `a, b`: after `,`
        pieces.push_back(rtrim(code.substr(from, cut - from)));
        from = cut;
        while (from < code.size() && code[from] == ' ') ++from;
    }
    pieces.push_back(code.substr(from));
    std::string line = pieces[0];
    bool first = true;
    auto flush = [&] {
        const std::string& in = first ? indent : more;
        // Deeper separators; their continuation one step in from this piece's own.
        if (in.size() + line.size() > width) wrap(in, more + "    ", line, width, out);
        else out += in + line + "\n";
        first = false;
    };
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        const std::string& in = first ? indent : more;
        if (in.size() + line.size() + 1 + pieces[i].size() <= width) {
            line += " " + pieces[i];
        } else {
            flush();
            line = pieces[i];
        }
    }
    flush();
}

}  // namespace

std::string wrapLongLines(const std::string& text, std::size_t width) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        const std::size_t code = line.find_first_not_of(' ');
        if (line.size() <= width || code == std::string::npos || line.compare(code, 2, "//") == 0) {
            out += line;
        } else {
            std::string wrapped;
            wrap(line.substr(0, code), line.substr(0, code) + "    ", line.substr(code), width, wrapped);
            wrapped.pop_back();   // its last newline: the text's own follows
            out += wrapped;
        }
        if (end < text.size()) out += '\n';
        start = end + 1;
    }
    return out;
}

}  // namespace g2d::import

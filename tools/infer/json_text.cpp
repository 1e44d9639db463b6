#include "infer/json_text.hpp"

#include "infer/example_shape.hpp"

namespace g2d::infer {
namespace {

using nlohmann::json;

// The DOM builder, keeping the first problem and its byte offset instead of
// throwing (it would throw out_of_range.406 with no position).
class LocatingBuilder : public nlohmann::detail::json_sax_dom_parser<json> {
public:
    explicit LocatingBuilder(json& result) : json_sax_dom_parser(result, false) {}
    template <class Exception>
    bool parse_error(std::size_t offset, const std::string& token, const Exception& problem) {
        if (!failed) {
            failed = true;
            // `offset` counts the bytes read: a number's, its whole token; a syntax error's, up to the bad byte.
            const bool overflow = problem.id == 406;
            const std::size_t back = overflow ? token.size() : 1;
            start = offset >= back ? offset - back : 0;
            message = overflow ? "the number " + token + " is out of range" : describe(problem.what());
        }
        return false;
    }
    bool failed = false;
    std::size_t start = 0;  // where the problem is
    std::string message;

private:
    // nlohmann's text after "[json.exception.parse_error.101] parse error at line 1, column 2: ".
    static std::string describe(const std::string& what) {
        const auto colon = what.find(": ");
        return colon == std::string::npos ? what : what.substr(colon + 2);
    }
};

}  // namespace

json parseJsonText(const std::string& text, const std::string& where) {
    json result;
    LocatingBuilder builder(result);
    const bool ok = json::sax_parse(text, &builder);
    if (ok && !builder.failed) return result;
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < builder.start && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, column = 1;
        else ++column;
    }
    throw InputError{where + ":" + std::to_string(line) + ":" + std::to_string(column) + ": not valid JSON: " +
                     (builder.message.empty() ? "it ends early" : builder.message)};
}

}  // namespace g2d::infer

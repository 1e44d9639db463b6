#pragma once
// JSON text to a document, every problem located: a syntax error, and a
// number beyond double's range (nlohmann reports that as out_of_range, not as
// a parse error, and without a position), both as "WHERE:LINE:COLUMN: ...".
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::infer {

// `where` names the text in messages (a path, or a path and the embedding
// field). Throws InputError.
nlohmann::json parseJsonText(const std::string& text, const std::string& where);

}  // namespace g2d::infer

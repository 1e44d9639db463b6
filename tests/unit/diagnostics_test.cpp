// Rendering of diagnostics: text with a caret, and JSON for editors.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "diag/diagnostic.hpp"

using namespace g2d;

TEST_CASE("text diagnostics show file:line:col, the line and a caret", "[diagnostics]") {
    SourceManager sm;
    FileId f = sm.add("dir/x.g2d", "node P;\n\tconst y = zz + 1;\n");
    Diagnostics diags;
    auto& d = diags.error(Span{f, 2, 12, 2, 14}, "unknown name `zz`");
    d.notes.push_back({Span{f, 1, 6, 1, 7}, "see here"});
    CHECK(renderText(d, sm) ==
          "dir/x.g2d:2:12: error: unknown name `zz`\n"
          "   const y = zz + 1;\n"
          "             ^~\n"
          "dir/x.g2d:1:6: note: see here\n"
          "  node P;\n"
          "       ^\n");
}

TEST_CASE("a caret counts characters, not bytes", "[diagnostics]") {
    SourceManager sm;
    FileId f = sm.add("u.g2d", "const s = \"ééé\" + 1;\n");
    Diagnostics diags;
    auto& d = diags.error(Span{f, 1, 17, 1, 18}, "bad");
    CHECK(renderText(d, sm) == "u.g2d:1:17: error: bad\n  const s = \"ééé\" + 1;\n                  ^\n");
}

TEST_CASE("file-level diagnostics have no line", "[diagnostics]") {
    SourceManager sm;
    FileId f = sm.add("missing.g2d", "");
    Diagnostics diags;
    auto& d = diags.error(Span{f, 0, 0, 0, 0}, "cannot open `missing.g2d`: no such file");
    CHECK(renderText(d, sm) == "missing.g2d: error: cannot open `missing.g2d`: no such file\n");
}

TEST_CASE("JSON diagnostics carry ranges, severity and notes", "[diagnostics]") {
    SourceManager sm;
    FileId f = sm.add("a.g2d", "x\ny\n");
    Diagnostics diags;
    diags.warning(Span{f, 2, 1, 2, 2}, "later");
    auto& e = diags.error(Span{f, 1, 1, 1, 2}, "first \"quoted\"");
    e.notes.push_back({Span{f, 2, 1, 2, 2}, "note"});
    auto j = nlohmann::json::parse(renderJson(diags.sorted(), sm));
    REQUIRE(j.size() == 2);
    CHECK(j[0]["message"] == "first \"quoted\"");
    CHECK(j[0]["severity"] == "error");
    CHECK(j[0]["file"] == "a.g2d");
    CHECK(j[0]["line"] == 1);
    CHECK(j[0]["column"] == 1);
    CHECK(j[0]["end_column"] == 2);
    CHECK(j[0]["notes"][0]["line"] == 2);
    CHECK(j[1]["severity"] == "warning");
}

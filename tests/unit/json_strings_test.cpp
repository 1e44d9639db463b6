// JSON strings are escaped by one function (rt::jsonString): the JSON
// writer's and the seed batch's summary lines write the same text.
#include <catch2/catch.hpp>

#include "g2d/json_writer.hpp"
#include "g2d/seed_rows.hpp"

using namespace g2d::rt;

TEST_CASE("one JSON string escaper: the writer's and the seed summary's", "[json]") {
    const std::string awkward = "a \"quoted\"\tpath\\to\x01 here";
    CHECK(jsonString(awkward) == "\"a \\\"quoted\\\"\\tpath\\\\to\\u0001 here\"");
    SeedRow row;
    row.seed = 3;
    row.status = 1;
    row.stopped = "error";
    row.messages = awkward + "\nsecond line";
    const std::string line = summaryLine(row);
    CHECK(line.find("\"error\": " + jsonString(awkward) + "}") != std::string::npos);
}

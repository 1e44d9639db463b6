#pragma once
// CSS colours as the SVG reads them, as numbers: for the exports that carry
// a style's colours into other formats (OBJ's MTL, glTF) and the example
// reader (tools/infer). One parser, so every output agrees on a colour.
#include <optional>
#include <string_view>

namespace g2d::rt {

struct Rgba {
    double r = 0, g = 0, b = 0, a = 1;   // each 0..1 (sRGB, as written)
};

// #rgb, #rgba, #rrggbb, #rrggbbaa, rgb()/rgba() (numbers or percentages,
// commas or spaces, alpha after `,` or `/`), hsl()/hsla(), the CSS named
// colours and `transparent`, in any case; nullopt for anything else
// (`none` included).
std::optional<Rgba> cssColor(std::string_view text);

}  // namespace g2d::rt

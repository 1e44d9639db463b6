#pragma once
// What the 3D exports (OBJ's MTL, glTF) carry of the drawing's styles, read
// in one place so that both agree with each other and with the SVG: a face's
// `fill` (default #d9d9d9, as the SVG draws it) and `fill_opacity`, an
// edge's `stroke` (default black) and `stroke_opacity`, as a colour and a
// material name made of it ("fill_8cc3df", "fill_8cc3df80" when translucent),
// one material per distinct colour.
#include <stdexcept>
#include <string>

#include "g2d/css_color.hpp"
#include "g2d/svg_writer.hpp"

namespace g2d::rt {

struct ExportMaterial {
    Rgba colour;        // sRGB as written; `a` the opacity (0 for `none`)
    std::string name;
};

ExportMaterial faceMaterial(const DrawItem& face);
ExportMaterial edgeMaterial(const DrawItem& edge);

// A model an export cannot write (a face that has no triangles): the run's
// outputs are not written, and the message says which face and why.
class ExportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace g2d::rt

#!/usr/bin/env bash
# Images in the SVG: a grammar names an image relative to its own file; the
# SVG links it relative to where it is written, or embeds it as a data: URI
# with --embed-images (interpreted and compiled alike); an image that cannot
# be embedded is an error that writes nothing.
# Usage: image_links_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
has() { grep -qF -- "$2" "$1" || fail "$1 lacks: $2"; }

mkdir -p grammar/pics out/deep
printf 'PIXELS' > grammar/pics/dot.png      # any bytes: only linked or embedded
cat > grammar/pic.g2d <<'G2D'
node Pic { src: string = "pics/dot.png"; style { tag = "image"; href = src; width = 1; height = 1; } }
axiom {
    a: Pic at (0, 0);
    b: Pic at (2, 0);
    c: Pic at (4, 0) { src = "https://example.org/x.png" };
}
G2D
expect_code 0 "$g2d" run grammar/pic.g2d -o out/deep/p.svg
has out/deep/p.svg 'href="../../grammar/pics/dot.png"'
has out/deep/p.svg 'href="https://example.org/x.png"'
expect_code 0 "$g2d" run grammar/pic.g2d -o grammar/p.svg
has grammar/p.svg 'href="pics/dot.png"'
expect_code 0 "$g2d" run grammar/pic.g2d -o out/e.svg --embed-images
# base64 of "PIXELS"
[ "$(grep -o 'href="data:image/png;base64,UElYRUxT"' out/e.svg | wc -l)" = 2 ] || fail "both images embedded"
has out/e.svg 'href="https://example.org/x.png"'

# The compiled program writes the same bytes.
expect_code 0 "$g2d" build grammar/pic.g2d -o pic_exe
expect_code 0 ./pic_exe -o out/deep/c.svg
cmp -s out/deep/p.svg out/deep/c.svg || fail "compiled links differ"
expect_code 0 ./pic_exe -o out/c_e.svg --embed-images
cmp -s out/e.svg out/c_e.svg || fail "compiled embedded images differ"

# A missing image cannot be embedded: exit 1, located, no file.
rm grammar/pics/dot.png
expect_code 1 "$g2d" run grammar/pic.g2d -o out/gone.svg --embed-images
has err.txt 'cannot embed the image `pics/dot.png`'
[ -e out/gone.svg ] && fail "a failed embedding wrote its SVG"
# Linking does not need the file.
expect_code 0 "$g2d" run grammar/pic.g2d -o out/link.svg
finish

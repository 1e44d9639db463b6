#!/usr/bin/env bash
# Hostile inputs and outputs (docs/robustness.md): each gets a located,
# readable error and a non-zero exit, never a crash, and never a truncated
# output file; CRLF and BOM files are valid input.
# Usage: hostile_files_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
koch="$src/examples/koch_snowflake.g2d"

# CRLF line ends and a UTF-8 byte-order mark are valid, and change nothing.
sed 's/$/\r/' "$koch" > crlf.g2d
printf '\xef\xbb\xbf' > bom.g2d; cat "$koch" >> bom.g2d
expect_code 0 "$g2d" run "$koch" -D max_lod=2 -o lf.svg
expect_code 0 "$g2d" run crlf.g2d -D max_lod=2 -o crlf.svg
expect_code 0 "$g2d" run bom.g2d -D max_lod=2 -o bom.svg
cmp -s lf.svg crlf.svg || fail "a CRLF file draws differently"
cmp -s lf.svg bom.svg || fail "a BOM file draws differently"
printf 'node P;\r\naxiom { a: Q; }\r\n' > crlf_bad.g2d
expect_code 1 "$g2d" check crlf_bad.g2d
grep -q '^crlf_bad.g2d:2:12: error: unknown node kind `Q`$' err.txt || fail "CRLF error location: $(cat err.txt)"

# A very long line: the error is located, and the excerpt is cut around it.
python3 -c "print('node P;\naxiom { a: P; }\nconst x = ' + '1 + ' * 2000 + 'zz;')" > long_line.g2d
expect_code 1 "$g2d" check long_line.g2d
grep -q '^long_line.g2d:3:8011: error: unknown name `zz`$' err.txt || fail "long line: $(head -c 300 err.txt)"
[ "$(wc -L < err.txt)" -lt 400 ] || fail "the excerpt of a long line is not cut: $(wc -L < err.txt) columns"
python3 - err.txt <<'PY' || fail "long line excerpt: $(sed -n 2,3p err.txt | head -c 400)"
import sys
lines = open(sys.argv[1], encoding="utf-8").read().split("\n")
source, caret = lines[1], lines[2]
assert source.startswith("  …") and source.endswith("zz;"), source
at = caret.index("^")
assert source[at:at + 2] == "zz", source[at - 5:at + 5]
PY

# Huge numeric literals
printf 'node P;\naxiom { a: P; }\nconst x = 99999999999999999999999999;\nconst y = 1e999;\n' > huge_numbers.g2d
expect_code 1 "$g2d" check huge_numbers.g2d
grep -q '^huge_numbers.g2d:3:11: error: integer literal is out of range' err.txt || fail "huge int: $(cat err.txt)"
grep -q '^huge_numbers.g2d:4:11: error: number literal is out of range' err.txt || fail "huge float: $(cat err.txt)"

# 10^5-deep nesting of every bracket
for open_close in '( )' '{ }' '[ ]'; do
  set -- $open_close
  python3 -c "print('const x = ' + '$1' * 100000 + '1' + '$2' * 100000 + ';')" > deep.g2d
  expect_code 1 "$g2d" check deep.g2d
  grep -qE '^deep.g2d:1:[0-9]+: error: (nesting is too deep \(more than 200 levels\)|statement is too long \(more than 4000 operators\))$' err.txt \
    || fail "deep $1: $(head -c 300 err.txt)"
done

# Many productions: 10^5 compile; 10^6 is over the file-size limit (8 MiB), refused at once.
python3 - <<'PY'
with open("many_rules.g2d", "w") as f:
    f.write("node P { n: int = 0; }\naxiom { a: P at (0, 0); }\nlimit 3;\n")
    for i in range(100000):
        f.write(f"rule R{i} {{ match {{ p: P where p.n == {i}; }} produce {{ p {{ n = p.n + 1 }}; }} }}\n")
with open("million_rules.g2d", "w") as f:
    f.write("node P;\naxiom { a: P; }\n")
    for i in range(1000000):
        f.write(f"rule R{i} {{ match {{ p: P; }} produce {{ p; }} }}\n")
PY
expect_code 0 "$g2d" run many_rules.g2d --no-svg --stats
grep -q '"steps": 3,' out.txt || fail "10^5 rules: $(cat out.txt)"
expect_code 1 "$g2d" check million_rules.g2d
grep -q "^million_rules.g2d: error: \`million_rules.g2d\` is too large ([0-9]* bytes; the limit is 8388608)$" err.txt \
  || fail "10^6 rules: $(cat err.txt)"

# More kinds than elements can record (32 767)
python3 -c "print('\n'.join(f'node K{i};' for i in range(40000)) + '\naxiom { a: K0; }')" > many_kinds.g2d
expect_code 1 "$g2d" check many_kinds.g2d
[ "$(grep -c error: err.txt)" = 1 ] && grep -q '^many_kinds.g2d:32768:6: error: too many kinds: a grammar may declare at most 32767 node, edge and face kinds$' err.txt \
  || fail "too many kinds: $(head -c 300 err.txt)"

# More style properties than the runtime numbers (65 535): 70 axiom nodes
# of 1 000 each, one a line; the 65 536th is n65's 536th
python3 - <<'PY'
lines = ["node P;", "axiom {"]
for n in range(70):
    lines.append(f"  n{n}: P {{ " + ", ".join(f"style.p{n * 1000 + i} = 1" for i in range(1000)) + " };")
open("many_styles.g2d", "w").write("\n".join(lines + ["}"]) + "\n")
PY
expect_code 1 "$g2d" check many_styles.g2d
[ "$(grep -c error: err.txt)" = 1 ] && grep -q '^many_styles.g2d:68:9648: error: too many style properties: a program may set at most 65535 different ones$' err.txt \
  || fail "too many style properties: $(head -c 300 err.txt)"

# Imports: a self-import, a cycle, a missing file, a folder, a symbolic-link loop
printf 'import "self.g2d";\nnode P;\naxiom { a: P; }\n' > self.g2d
expect_code 1 "$g2d" check self.g2d
grep -q '^self.g2d:1:1: error: import cycle: `self.g2d` → `self.g2d`$' err.txt || fail "self-import: $(cat err.txt)"
printf 'import "b.g2d";\nnode P;\naxiom { a: P; }\n' > a.g2d
printf 'import "a.g2d";\n' > b.g2d
expect_code 1 "$g2d" check a.g2d
grep -q 'error: import cycle: `a.g2d` → `b.g2d` → `a.g2d`$' err.txt || fail "import cycle: $(cat err.txt)"
ln -s loop2.g2d loop1.g2d; ln -s loop1.g2d loop2.g2d
expect_code 1 "$g2d" check loop1.g2d
grep -q '^loop1.g2d: error: cannot open `loop1.g2d`: Too many levels of symbolic links$' err.txt || fail "symlink loop: $(cat err.txt)"
printf 'import "loop1.g2d";\nnode P;\naxiom { a: P; }\n' > imports_loop.g2d
expect_code 1 "$g2d" check imports_loop.g2d
grep -q '^imports_loop.g2d:1:1: error: cannot open `loop1.g2d`: Too many levels of symbolic links$' err.txt || fail "import of a symlink loop: $(cat err.txt)"
printf 'import "/dev/zero";\nnode P;\naxiom { a: P; }\n' > dev.g2d
expect_code 1 "$g2d" check dev.g2d
grep -q "^dev.g2d:1:1: error: cannot read \`/dev/zero\`: not a regular file$" err.txt || fail "import of a device: $(cat err.txt)"
mkdir folder.g2d
expect_code 1 "$g2d" check folder.g2d

# Unreadable files (root reads everything: then there is nothing to test)
if [ "$(id -u)" != 0 ]; then
  cp "$koch" unreadable.g2d; chmod 000 unreadable.g2d
  expect_code 1 "$g2d" check unreadable.g2d
  grep -q 'error: cannot open `unreadable.g2d`: Permission denied' err.txt || fail "unreadable: $(cat err.txt)"
fi

# Outputs: a missing folder, a place nobody may write (even root), a folder
expect_code 1 "$g2d" run "$koch" -D max_lod=1 -o missing/dir/out.svg
grep -q "error: cannot write \`missing/dir/out.svg\`: No such file or directory" err.txt || fail "missing folder: $(cat err.txt)"
expect_code 1 "$g2d" run "$koch" -D max_lod=1 -o /proc/g2d-out.svg
grep -q "error: cannot write \`/proc/g2d-out.svg\`" err.txt || fail "/proc: $(cat err.txt)"
mkdir outdir
expect_code 1 "$g2d" run "$koch" -D max_lod=1 -o outdir
grep -q "error: cannot write \`outdir\`: it is a directory" err.txt || fail "folder as output: $(cat err.txt)"

# A full disk, simulated by a file-size limit: the write fails with the
# system's reason, and the old output stays whole (no truncated file, no temporary).
expect_code 0 "$g2d" run "$koch" -D max_lod=1 -o full.svg --json full.json
cp full.svg full.before; cp full.json full.json.before
( ulimit -f 8; exec "$g2d" run "$koch" -D max_lod=5 -o full.svg --json full.json ) >out.txt 2>err.txt; got=$?
[ "$got" = 1 ] || fail "disk full: exit $got -- $(cat err.txt)"
grep -q "error: cannot write \`full.svg\`: File too large" err.txt || fail "disk full message: $(cat err.txt)"
cmp -s full.svg full.before || fail "disk full: the old SVG was damaged"
cmp -s full.json full.json.before || fail "disk full: the old JSON was damaged"
ls | grep -q '\.tmp-' && fail "disk full left temporary files: $(ls | grep tmp-)"

# Special files are written through, never replaced (tested on our own links
# and FIFOs: a regression must not replace the machine's /dev/stdout or /dev/null);
# symbolic links are followed.
ln -s /proc/self/fd/1 my_stdout
expect_code 0 "$g2d" run "$koch" -D max_lod=1 -o my_stdout
head -c 38 out.txt | grep -q '<?xml' || fail "-o to stdout (a file) wrote no SVG"
[ -L my_stdout ] || fail "the link to stdout was replaced"
"$g2d" run "$koch" -D max_lod=1 -o my_stdout | head -c 38 | grep -q '<?xml' || fail "-o to stdout (a pipe) wrote no SVG"
[ -L my_stdout ] || fail "the link to stdout was replaced (pipe)"
mkfifo fifo.svg
( cat fifo.svg > from_fifo.svg ) &
expect_code 0 "$g2d" run "$koch" -D max_lod=1 -o fifo.svg
wait
[ -p fifo.svg ] || fail "a FIFO was replaced"
cmp -s from_fifo.svg lf1.svg 2>/dev/null || head -c 38 from_fifo.svg | grep -q '<?xml' || fail "nothing came through the FIFO"
mkdir real; ln -s real/target.svg link.svg
expect_code 0 "$g2d" run "$koch" -D max_lod=1 -o link.svg
[ -L link.svg ] && [ -s real/target.svg ] || fail "a symbolic link was replaced instead of followed"

finish

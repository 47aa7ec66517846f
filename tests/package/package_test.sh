#!/usr/bin/env bash
# `cmake --install` of the build into a fresh prefix, then a separate CMake project (and a pkg-config
# build) against that prefix alone: the consumer renders, and its picture is the CLI's.
# Usage: package_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
libdir=$(dirname "$(find "$prefix" -name 'libillum.so' | head -1)")

echo "installed: $(cd "$prefix" && find . -type f -o -type l | sort | tr '\n' ' ')"
for f in bin/illum bin/illum-view include/illum/illum.h include/illum/error.h share/man/man1/illum.1 share/man/man1/illum-render.1 \
         share/thumbnailers/illum.thumbnailer; do
  [ -e "$prefix/$f" ] || { echo "missing from the install: $f"; exit 1; }
done
# Only the API: no header of the internals.
[ "$(ls "$prefix/include/illum")" = "$(printf 'error.h\nillum.h')" ] || { echo "headers beyond the API: $(ls "$prefix/include/illum")"; exit 1; }
grep -q -- 'resolution' "$prefix/share/man/man1/illum-render.1" || { echo "illum-render(1) lacks --resolution"; exit 1; }
grep -q '^\.TH ILLUM' "$prefix/share/man/man1/illum.1" || { echo "illum(1) is not a man page"; exit 1; }

model=/usr/share/assimp/models/Collada/duck.dae
cmake -S "$source/tests/package" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
out=$(LD_LIBRARY_PATH="$libdir" "$work/consumer/consumer" "$model" "$work/consumer.png")
echo "$out"
"$prefix/bin/illum" render "$model" --resolution 200,150 --camera-azimuth-angle 30 -o "$work/cli.png" -q
cmp "$work/consumer.png" "$work/cli.png" || { echo "the library's picture differs from the CLI's"; exit 1; }
expected="version 0.1.0
model 200x150
sphere centre 153 51 255
diffuse at 60 degrees 0.5000
refused: --size: not an option of illum render; did you mean --resolution? (illum render --help lists them)"
[ "$out" = "$expected" ] || { echo "expected:"; echo "$expected"; exit 1; }

# pkg-config, as a Makefile would use it.
export PKG_CONFIG_PATH="$libdir/pkgconfig"
g++ -std=c++17 "$source/tests/package/consumer.cpp" -o "$work/consumer-pc" $(pkg-config --cflags --libs illum)
[ "$(LD_LIBRARY_PATH="$libdir" "$work/consumer-pc" "$model" "$work/pc.png")" = "$expected" ]
cmp "$work/pc.png" "$work/cli.png"
echo "package test: passed"

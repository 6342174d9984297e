#!/bin/sh
# Writes the pictures that scenes/poseray.pov maps on its mesh (and that
# scenes/water.pov's quay takes as its bump_map), as a mesh exporter would
# ship them beside its scene: crate.png (64x64, 8-bit RGB),
# planks of a wood pattern, and stone.jpg (64x64, baseline JPEG at
# quality 85, the default), veined marble. Each is a render of a small
# procedural scene (below) seen flat on by an orthographic camera, lit by
# ambient only, so that the picture holds the pattern's colours.
#
# usage: make-textures.sh [HSTRACE]
#   HSTRACE  the renderer (default: hstrace on PATH); POV-Ray 3.7 makes
#            pictures of the same pixels (measured with hstrace compare):
#            make-textures.sh povray
# Writes into the folder this script is in. Exit status: 0 done, 1 a render
# failed, 3 no renderer.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
render=${1:-hstrace}
command -v "$render" >/dev/null 2>&1 || { echo "make-textures: $render not found" >&2; exit 3; }
# the renders run in a scratch folder: a relative path made absolute
case $render in */*) render=$(cd "$(dirname "$render")" && pwd)/$(basename "$render") ;; esac
work=$(mktemp -d "${TMPDIR:-/tmp}/hsttextures.XXXXXX")
trap 'rm -rf "$work"' EXIT
# scene NAME PIGMENT: a square of PIGMENT filling a 64x64 picture.
scene() {
    cat >"$work/$1.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1>
  pigment { $2 }
  finish { ambient 1 diffuse 0 } }
POV
}
scene crate 'wood turbulence 0.08 colour_map { [0 rgb <0.62, 0.40, 0.20>] [0.6 rgb <0.80, 0.58, 0.32>] [1 rgb <0.45, 0.27, 0.12>] }
    scale <0.05, 1, 0.05> rotate x*90 rotate z*3 translate <0.3, 0, 0>'
scene stone 'marble turbulence 0.9 colour_map { [0 rgb <0.92, 0.90, 0.86>] [0.7 rgb <0.80, 0.78, 0.76>]
    [0.9 rgb <0.35, 0.38, 0.48>] [1 rgb <0.20, 0.22, 0.30>] } scale 0.5 rotate z*30'
(cd "$work" && "$render" +Icrate.pov +W64 +H64 -A -D -GA +FN +Ocrate.png &&
    "$render" +Istone.pov +W64 +H64 -A -D -GA +FJ +Ostone.jpg) >"$work/log" 2>&1 ||
    { echo "make-textures: $render failed:" >&2; cat "$work/log" >&2; exit 1; }
mv "$work/crate.png" "$work/stone.jpg" "$here/"

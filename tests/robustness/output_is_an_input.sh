#!/bin/sh
# output_is_an_input.sh PROGRAM OBJ_DIR WORK: copies the crate model into
# WORK and asks PROGRAM to write its render over the model's own texture, by
# its name and through a symbolic link. Each run must fail saying the file
# was read as an input, and the texture must be left as it was.
set -u
program="$1" obj="$2" work="$3/crate_copy"
rm -rf "$work" && mkdir -p "$work" && cp "$obj"/crate* "$work"/ || exit 1
ln -s crate_diffuse.tga "$work/render.tga" || exit 1
for out in crate_diffuse.tga render.tga; do
    if "$program" --model "$work/crate.obj" -o "$work/$out" 2>"$work/err.txt"; then
        echo "-o $out was accepted"
        exit 1
    fi
    cat "$work/err.txt"
    grep -q "is a file this run read as an input" "$work/err.txt" || exit 1
    cmp "$obj/crate_diffuse.tga" "$work/crate_diffuse.tga" || exit 1
done

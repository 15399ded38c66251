#!/bin/sh
# A "program" that ignores its input and writes a recorded output: DIR/rec.node,
# DIR/rec.ele and DIR/rec.trace as {out}.node, .ele, .trace.
# usage: recorded.sh DIR {in} {out}
dir=$1; out=$3
cp "$dir/rec.node" "$out.node" && cp "$dir/rec.ele" "$out.ele" && cp "$dir/rec.trace" "$out.trace"

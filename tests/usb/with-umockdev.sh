#!/bin/sh
# Runs a test program under umockdev's preload library (umockdev-wrapper).
# In the sanitizer build the preload library comes before the ASan runtime in
# the library list, which ASan refuses by default; it is expected here.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS
exec umockdev-wrapper "$@"

# Sourced by the build scripts (from the checkout's root): ccache, which
# tools/setup.sh installs, for every preset, keyed on paths below the checkout
# (CCACHE_BASEDIR) and not on the build folder (CCACHE_NOHASHDIR), so that a
# fresh clone on a machine that built rayspec before compiles only what
# differs. Sets `launcher` (cmake arguments; empty without ccache).
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # pch_defines, time_macros: what ccache needs to cache files compiled with
  # the tests' precompiled header (tests/CMakeLists.txt).
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1 CCACHE_SLOPPINESS=pch_defines,time_macros
fi

// The translation unit that builds the tests' precompiled header (catch2/catch.hpp, once
// per build; tests/CMakeLists.txt: cuetrack_test_pch). Nothing of its own.

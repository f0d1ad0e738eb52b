// The translation unit that the test binaries' shared precompiled header is built with
// (tests/CMakeLists.txt, mhd_test_pch). It has no code of its own.

// Compiles the test suites' precompiled header, support/precompiled_headers.hpp
// (tests/CMakeLists.txt, wifislam_test_pch), which every suite reuses.

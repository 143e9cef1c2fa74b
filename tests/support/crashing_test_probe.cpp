// A suite whose one test dies of SIGSEGV, for test_main_test.cpp: it shows what a crashed test
// process prints. Not a ctest test; only test_main_test runs it.

#include <gtest/gtest.h>

#include <csignal>

TEST(CrashingProbe, DiesOfASegmentationFault) { std::raise(SIGSEGV); }

// core/utf8.hpp against the forms RFC 3629 allows and refuses.
#include "core/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

namespace wifislam {
namespace {

TEST(Utf8, WellFormedTextIsValid) {
  for (const std::string text : {"", "plain ascii/path.yaml", "caf\xC3\xA9", "\xE2\x82\xAC 5",
                                 "\xF0\x9F\x93\xB6 wifi", "\xED\x9F\xBF", "\xF4\x8F\xBF\xBF"}) {
    EXPECT_TRUE(is_valid_utf8(text)) << text;
  }
}

TEST(Utf8, Latin1OverlongSurrogatesAndTruncatedFormsAreNot) {
  for (const std::string text : {
           "d\xff\xfe",         // Latin-1 bytes of a file name
           "caf\xE9",           // é in Latin-1
           "\xC0\xAF",          // overlong '/'
           "\xE0\x80\xAF",      // overlong '/', three bytes
           "\xED\xA0\x80",      // a UTF-16 surrogate
           "\xF4\x90\x80\x80",  // above U+10FFFF
           "\x80 alone",        // a continuation byte first
           "\xE2\x82",          // truncated at the end
           "\xE2\x28\xA1",      // a second byte that is no continuation
       }) {
    EXPECT_FALSE(is_valid_utf8(text)) << text;
  }
}

}  // namespace
}  // namespace wifislam

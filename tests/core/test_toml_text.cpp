// toml_string: any bytes give a valid TOML basic string (config.toml holds paths and command lines).
#include <catch2/catch.hpp>

#include <string>

#include "hm/core/toml_text.hpp"

using hm::core::toml_string;

TEST_CASE("toml_string escapes quotes, backslashes and control characters and keeps valid UTF-8", "[core]") {
  CHECK(toml_string("out/run") == "\"out/run\"");
  CHECK(toml_string("a\"b\\c") == "\"a\\\"b\\\\c\"");
  CHECK(toml_string("a\nb\tc\rd") == "\"a\\nb\\tc\\u000dd\"");
  CHECK(toml_string(std::string("nul\0x", 5)) == "\"nul\\u0000x\"");
  CHECK(toml_string("\x7f") == "\"\\u007f\"");
  // Two-, three- and four-byte sequences pass unchanged: é, €, U+1D11E.
  CHECK(toml_string("\xc3\xa9 \xe2\x82\xac \xf0\x9d\x84\x9e") == "\"\xc3\xa9 \xe2\x82\xac \xf0\x9d\x84\x9e\"");
}

TEST_CASE("toml_string writes each byte that is not UTF-8 as U+FFFD", "[core]") {
  CHECK(toml_string("a\xff"
                    "b") == "\"a\\ufffdb\"");                                    // never a UTF-8 byte
  CHECK(toml_string("\x80") == "\"\\ufffd\"");                                   // stray continuation byte
  CHECK(toml_string("\xe2\x82") == "\"\\ufffd\\ufffd\"");                        // truncated sequence
  CHECK(toml_string("\xc0\xaf") == "\"\\ufffd\\ufffd\"");                        // overlong '/'
  CHECK(toml_string("\xed\xa0\x80") == "\"\\ufffd\\ufffd\\ufffd\"");             // surrogate U+D800
  CHECK(toml_string("\xf4\x90\x80\x80") == "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");  // beyond U+10FFFF
  CHECK(toml_string("\xe2\x82\xac\xe2") == "\"\xe2\x82\xac\\ufffd\"");           // valid, then cut off
}

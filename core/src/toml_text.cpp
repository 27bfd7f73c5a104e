#include "hm/core/toml_text.hpp"

#include <cstdio>
#include <ctime>

namespace hm::core {

namespace {

// Length of the well-formed UTF-8 sequence starting at s[i] (1 to 4 bytes), or 0 if the bytes there
// are none (a stray continuation byte, a truncated sequence, an overlong form, a surrogate, a code
// point beyond U+10FFFF): the Unicode standard's table of well-formed sequences.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xbf;  // the second byte's range; later bytes are 80..BF
  if (lead >= 0xc2 && lead <= 0xdf)
    n = 2;
  else if (lead == 0xe0)
    n = 3, lo = 0xa0;
  else if (lead >= 0xe1 && lead <= 0xef)
    n = 3, hi = lead == 0xed ? 0x9f : 0xbf;
  else if (lead == 0xf0)
    n = 4, lo = 0x90;
  else if (lead >= 0xf1 && lead <= 0xf3)
    n = 4;
  else if (lead == 0xf4)
    n = 4, hi = 0x8f;
  else
    return 0;
  if (i + n > s.size() || byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  return n;
}

}  // namespace

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      // A TOML file is UTF-8 and a Linux path is any bytes: a byte that is no UTF-8 becomes U+FFFD,
      // so the file reads back and shows where the byte was (the original byte is not recoverable).
      out += "\\ufffd";
      ++i;
      continue;
    }
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {  // TOML allows no raw control character in a basic string
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out.append(s, i, n);
    }
    i += n;
  }
  return out + "\"";
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return stamp;
}

}  // namespace hm::core

// new_token / token_shaped: RAND_bytes into hex.
#include "studyapp/web/web_token.hpp"

#include <openssl/rand.h>

#include <array>
#include <stdexcept>

namespace ms::web {

std::string new_token() {
  std::array<unsigned char, kTokenBytes> bytes{};
  if (RAND_bytes(bytes.data(), static_cast<int>(bytes.size())) != 1)
    throw std::runtime_error("the system's random source failed (RAND_bytes)");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text;
  for (const unsigned char b : bytes) {
    text += kHex[b >> 4];
    text += kHex[b & 0x0f];
  }
  return text;
}

bool token_shaped(const std::string& text) {
  if (text.size() < 2 * kTokenBytes || text.size() > 128) return false;
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

std::string new_sound_id() { return new_token(); }

}  // namespace ms::web

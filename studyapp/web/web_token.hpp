// Participant link tokens: 128 random bits from OpenSSL's RAND_bytes, written as 32 lower-case hex
// digits. A token is the only thing a link carries; it says nothing about the participant.
#pragma once
#include <string>

namespace ms::web {

inline constexpr std::size_t kTokenBytes = 16;  // 128 bits

// Throws std::runtime_error if the system's random source fails (never a weaker token).
std::string new_token();

// The shape a token must have before it is looked up: 32..128 characters of [0-9a-f]. Anything else
// (a path, a name, a short guess) is refused without a lookup.
bool token_shaped(const std::string& text);

// An opaque id for one sound of one trial: 128 random bits, hex; unrelated to its name or recipe.
std::string new_sound_id();

}  // namespace ms::web

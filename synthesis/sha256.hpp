// SHA-256 of bytes or a file, as lowercase hex (OpenSSL EVP).
#pragma once
#include <string>

namespace ms {

std::string sha256_hex(const std::string& bytes);
std::string sha256_file_hex(const std::string& path);  // throws InputError if unreadable

}  // namespace ms

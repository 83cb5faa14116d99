// libFuzzer entry point: the webMUSHRA config importer (see fuzz_inputs.hpp; built and run by scripts/fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ms::fuzz::webmushra(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}

#pragma once
// CRC-32C (Castagnoli, reflected polynomial 0x82F63B78), the checksum of the checkpoint logs
// (runner/checkpoint.hpp): it detects every error of up to 3 bits and every burst of up to 32 bits
// in records of these lengths. crc32c(data, size, crc32c(prefix)) is the CRC of prefix + data.
#include <cstddef>
#include <cstdint>

namespace geomint {

std::uint32_t crc32c(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace geomint

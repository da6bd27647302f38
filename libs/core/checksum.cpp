#include "core/checksum.hpp"

#include <cstring>

namespace rockfrac {

namespace {

std::uint64_t loadLittleEndian64(const unsigned char* p)
{
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

}  // namespace

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash)
{
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= fnv1aPrime;
    }
    return hash;
}

std::uint64_t fnv1aWords(const void* data, std::size_t size)
{
    const auto* p = static_cast<const unsigned char*>(data);
    std::uint64_t hash = fnv1aOffsetBasis;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) hash = (hash ^ loadLittleEndian64(p + i)) * fnv1aPrime;
    if (i < size) {
        unsigned char tail[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        std::memcpy(tail, p + i, size - i);
        hash = (hash ^ loadLittleEndian64(tail)) * fnv1aPrime;
    }
    return (hash ^ size) * fnv1aPrime;
}

}  // namespace rockfrac

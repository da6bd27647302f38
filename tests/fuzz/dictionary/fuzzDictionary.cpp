// libFuzzer target: arbitrary bytes as a dictionary file. The only allowed
// outcome besides success is a UserError; anything else (a crash, a sanitizer
// report, another exception, a hang) is a bug. When a text parses, two more
// promises are checked: the canonical form reads back to itself, and the
// editor either edits or refuses with a UserError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "../common/fuzzTarget.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"

namespace {

// Small enough that a doubling macro chain fails fast under the sanitizers.
rockfrac::ParseLimits fuzzLimits()
{
    rockfrac::ParseLimits limits;
    limits.maxValues = 100000;
    limits.allowIncludes = false;  // the fuzzer must not read /dev/zero or the disk
    return limits;
}

void checkRoundTrip(const rockfrac::Dictionary& dict)
{
    const std::string once = rockfrac::toString(dict);
    const rockfrac::Dictionary again = rockfrac::Dictionary::parse(once, "canonical", fuzzLimits());
    if (rockfrac::toString(again) != once) std::abort();
}

void exerciseEditor(const std::string& text, const rockfrac::Dictionary& dict)
{
    const std::string key = dict.keys().empty() ? std::string("fuzzKey") : dict.keys().front();
    try {
        (void)rockfrac::setEntry(text, key, "1", "fuzz", "comment");
        (void)rockfrac::setEntry(text, "fuzzNew/sub/key", "(1 2)", "fuzz");
        (void)rockfrac::removeEntry(text, key, "fuzz");
    } catch (const rockfrac::UserError&) {
    }
}

}  // namespace

namespace rockfrac::fuzz {

int fuzzDictionary(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const Dictionary dict = Dictionary::parse(text, "fuzz", fuzzLimits());
        checkRoundTrip(dict);
        exerciseEditor(text, dict);
    } catch (const UserError&) {
    }
    return 0;
}

}  // namespace rockfrac::fuzz

ROCKFRAC_FUZZ_ENTRY(rockfrac::fuzz::fuzzDictionary)

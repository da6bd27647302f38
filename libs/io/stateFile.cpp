#include "io/stateFile.hpp"

#include <cstring>
#include <fstream>

#include "core/atomicFile.hpp"
#include "core/checksum.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

constexpr char magic[8] = {'R', 'F', 'S', 'T', 'A', 'T', 'E', '\0'};
constexpr std::uint32_t version = 1;
enum TypeCode : std::uint8_t { typeDouble = 1, typeInt64 = 2, typeUint8 = 3 };

template <class T>
void append(std::string& out, const T& value)
{
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
void appendArray(std::string& out, const std::string& name, TypeCode type, const std::vector<T>& values)
{
    append(out, static_cast<std::uint32_t>(name.size()));
    out += name;
    append(out, static_cast<std::uint8_t>(type));
    append(out, static_cast<std::uint64_t>(values.size()));
    if (!values.empty()) out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// Bounds-checked reading of the file's bytes.
class Reader {
public:
    Reader(const std::string& bytes, const fs::path& file) : bytes_(bytes), file_(file) {}
    template <class T>
    T take(const char* what)
    {
        need(sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return value;
    }
    std::string takeString(std::size_t n, const char* what)
    {
        need(n, what);
        std::string s = bytes_.substr(pos_, n);
        pos_ += n;
        return s;
    }
    template <class T>
    std::vector<T> takeArray(std::uint64_t count, const std::string& name)
    {
        if (count > (bytes_.size() - pos_) / sizeof(T))
            fail("array '" + name + "' announces " + std::to_string(count) +
                 " values but the file is shorter");
        std::vector<T> values(count);
        if (count) std::memcpy(values.data(), bytes_.data() + pos_, count * sizeof(T));
        pos_ += count * sizeof(T);
        return values;
    }
    std::size_t position() const { return pos_; }
    [[noreturn]] void fail(const std::string& what) const
    {
        throw UserError(file_.string() + ": " + what +
                        "; the state file is corrupt or truncated: restart from an earlier time directory");
    }

private:
    void need(std::size_t n, const char* what) const
    {
        if (n > bytes_.size() - pos_) fail(std::string("truncated while reading ") + what);
    }
    const std::string& bytes_;
    fs::path file_;
    std::size_t pos_ = 0;
};

}  // namespace

void StateFile::put(const std::string& name, std::vector<double> values)
{
    doubles_[name] = std::move(values);
}
void StateFile::put(const std::string& name, std::vector<std::int64_t> values)
{
    integers_[name] = std::move(values);
}
void StateFile::put(const std::string& name, std::vector<std::uint8_t> values)
{
    bytes_[name] = std::move(values);
}
void StateFile::put(const std::string& name, const std::vector<Vec3>& values)
{
    std::vector<double> flat;
    flat.reserve(3 * values.size());
    for (const auto& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
    doubles_[name] = std::move(flat);
}

bool StateFile::has(const std::string& name) const
{
    return doubles_.count(name) || integers_.count(name) || bytes_.count(name);
}

void StateFile::erase(const std::string& name)
{
    doubles_.erase(name);
    integers_.erase(name);
    bytes_.erase(name);
}

void StateFile::missing(const std::string& name, const char* kind) const
{
    throw UserError(source_.string() + ": no " + kind + " array '" + name +
                    "'; the state was written by another solver or version: restart from time 0");
}

void StateFile::checkCount(const std::string& name, std::size_t count, long expected) const
{
    if (expected >= 0 && count != static_cast<std::size_t>(expected))
        throw UserError(source_.string() + ": array '" + name + "' has " + std::to_string(count) +
                        " values, the case needs " + std::to_string(expected) +
                        "; the state does not belong to this mesh: restart from time 0");
}

const std::vector<double>& StateFile::doubles(const std::string& name, long expectedCount) const
{
    auto it = doubles_.find(name);
    if (it == doubles_.end()) missing(name, "real");
    checkCount(name, it->second.size(), expectedCount);
    return it->second;
}

const std::vector<std::int64_t>& StateFile::integers(const std::string& name, long expectedCount) const
{
    auto it = integers_.find(name);
    if (it == integers_.end()) missing(name, "integer");
    checkCount(name, it->second.size(), expectedCount);
    return it->second;
}

const std::vector<std::uint8_t>& StateFile::bytes(const std::string& name, long expectedCount) const
{
    auto it = bytes_.find(name);
    if (it == bytes_.end()) missing(name, "byte");
    checkCount(name, it->second.size(), expectedCount);
    return it->second;
}

std::vector<Vec3> StateFile::vectors(const std::string& name, long expectedCount) const
{
    const auto& flat = doubles(name, expectedCount >= 0 ? 3 * expectedCount : -1);
    if (flat.size() % 3 != 0) checkCount(name, flat.size(), static_cast<long>(flat.size() / 3 * 3));
    std::vector<Vec3> v(flat.size() / 3);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
    return v;
}

void StateFile::write(const fs::path& file) const
{
    std::string out(magic, sizeof(magic));
    append(out, version);
    append(out, static_cast<std::uint32_t>(doubles_.size() + integers_.size() + bytes_.size()));
    for (const auto& [name, values] : doubles_) appendArray(out, name, typeDouble, values);
    for (const auto& [name, values] : integers_) appendArray(out, name, typeInt64, values);
    for (const auto& [name, values] : bytes_) appendArray(out, name, typeUint8, values);
    append(out, fnv1a(out.data(), out.size()));
    writeFileAtomically(
        file, [&](std::ostream& s) { s.write(out.data(), static_cast<std::streamsize>(out.size())); });
}

StateFile StateFile::read(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UserError(file.string() + ": cannot read the state file (missing or unreadable)");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parse(bytes, file);
}

StateFile StateFile::parse(const std::string& bytes, const fs::path& file)
{
    Reader r(bytes, file);
    if (r.takeString(sizeof(magic), "the magic string") != std::string(magic, sizeof(magic)))
        r.fail("not a rockfrac state file (wrong magic string)");
    const auto fileVersion = r.take<std::uint32_t>("the version");
    if (fileVersion != version)
        r.fail("state file version " + std::to_string(fileVersion) + " is not supported");
    const auto nArrays = r.take<std::uint32_t>("the array count");
    StateFile state;
    state.source_ = file;
    for (std::uint32_t a = 0; a < nArrays; ++a) {
        const auto nameLength = r.take<std::uint32_t>("an array name length");
        if (nameLength == 0 || nameLength > 256)
            r.fail("array " + std::to_string(a) + " has an invalid name length");
        const std::string name = r.takeString(nameLength, "an array name");
        const auto type = r.take<std::uint8_t>("an array type");
        const auto count = r.take<std::uint64_t>("an array length");
        if (state.has(name)) r.fail("array '" + name + "' appears twice");
        switch (type) {
            case typeDouble:
                state.doubles_[name] = r.takeArray<double>(count, name);
                break;
            case typeInt64:
                state.integers_[name] = r.takeArray<std::int64_t>(count, name);
                break;
            case typeUint8:
                state.bytes_[name] = r.takeArray<std::uint8_t>(count, name);
                break;
            default:
                r.fail("array '" + name + "' has unknown type code " + std::to_string(type));
        }
    }
    const std::size_t checked = r.position();
    const auto stored = r.take<std::uint64_t>("the checksum");
    if (stored != fnv1a(bytes.data(), checked)) r.fail("checksum mismatch");
    if (r.position() != bytes.size()) r.fail("unexpected bytes after the checksum");
    return state;
}

}  // namespace rockfrac

#pragma once
// Per-entity arrays declared once: each array group of demState.hpp (cells, interfaces,
// bonds, contact pairs, wall items) lists its arrays in one static function,
//
//     template <class Visit, class... Groups>
//     static void fields(Visit&& visit, Groups&... g)
//     {
//         visit(ArrayField<stateField>{"position", "m"}, g.position...);
//         visit(ArrayField<constantField | rangedField>{"coreVertices", "m"},
//               ranged(g.core_vertex_offset, g.core_vertices)...);
//     }
//
// and forEachField<With, Without>(fn, groups...) calls fn(field, array...) for each array
// whose flags include all of With and none of Without, over one or more instances of the
// group visited side by side (host and device mirror, a model and a restart file's copy).
// Everything that walks a group's arrays walks this list: appending and removing
// entities, shrinking, memory accounting, the CUDA mirror, the state file and packing one
// entity for migration (packEntity/unpackEntity below). The flags are compile-time, so an
// operation is only instantiated for the arrays it accepts.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rockfrac {

enum FieldFlag : unsigned {
    restartField = 1u << 0,   // in the state file <time>/demState ("<entity>.<name>")
    migrateField = 1u << 1,   // moves with its entity (packEntity: the MPI exchange)
    fixedField = 1u << 2,     // never changed by a step (a device mirror uploads, never downloads)
    derivedField = 1u << 3,   // recomputed: sized with its entity, its values rebuilt
    optionalField = 1u << 4,  // an empty array stands for ArrayField::neutral everywhere
    rangedField = 1u << 5,    // CSR children: ranged(offset, values), entity i owns [offset[i], offset[i+1])
    // Offsets into another group (an interface's bonds): rebuilt with that group, not per entity.
    childrenField = 1u << 6,
    // The softening pool (entries and each interface's first slot): a pool, not per entity;
    // a device mirror keeps one entry per bond instead.
    poolField = 1u << 7,
    carriedField = 1u << 8,   // history carried by key across neighbour-list rebuilds
    hostOnlyField = 1u << 9,  // output only: not mirrored on a device
    // Shorthands: the state of an entity (restarted and migrated), and its constants
    // (set when it is made, migrated, never written to a restart file).
    stateField = restartField | migrateField,
    constantField = migrateField | fixedField,
};

// What an array is: its name (the state-file entry after "<entity>."), its unit (SI, "-" for
// indices and dimensionless numbers) and, for optional arrays, the value an empty one means.
template <unsigned Flags>
struct ArrayField {
    static constexpr unsigned flags = Flags;
    const char* name;
    const char* unit;
    double neutral = 0.0;
};

// The flags of a visited field (in a generic lambda: flagsOf<decltype(field)>).
template <class FieldType>
constexpr unsigned flagsOf = std::decay_t<FieldType>::flags;

// "<entity>.<name>": the array's entry in the state file and in messages.
template <class Group, unsigned Flags>
std::string entryName(const ArrayField<Flags>& field)
{
    return std::string(Group::entity) + "." + field.name;
}

// A CSR child array with its offsets (one more than the entities).
template <class Offsets, class Values>
struct Ranged {
    Offsets& offset;
    Values& values;
};

template <class Offsets, class Values>
Ranged<Offsets, Values> ranged(Offsets& offset, Values& values)
{
    return {offset, values};
}

namespace fieldDetail {

template <unsigned With, unsigned Without, class Fn>
struct Filter {
    Fn& fn;
    template <unsigned Flags, class... Arrays>
    void operator()(const ArrayField<Flags>& field, Arrays&&... arrays) const
    {
        if constexpr ((Flags & With) == With && (Flags & Without) == 0u) fn(field, arrays...);
    }
};

template <class T>
struct IsRanged : std::false_type {
};
template <class O, class V>
struct IsRanged<Ranged<O, V>> : std::true_type {
};

}  // namespace fieldDetail

template <unsigned With, unsigned Without = 0u, class Fn, class First, class... Rest>
void forEachField(Fn&& fn, First& first, Rest&... rest)
{
    using Group = std::remove_const_t<First>;
    Group::fields(fieldDetail::Filter<With, Without, std::remove_reference_t<Fn>>{fn}, first, rest...);
}

// Arrays indexed by entity (not CSR, not offsets into another group, not the pool).
constexpr unsigned notPerEntity = rangedField | childrenField | poolField;

// ---- Host operations over one array (std::vector) or one CSR pair ----------------------

template <class T>
std::size_t capacityBytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}
template <class O, class V>
std::size_t capacityBytes(const Ranged<O, V>& r)
{
    return capacityBytes(r.offset) + capacityBytes(r.values);
}

template <class T>
std::size_t sizeBytes(const std::vector<T>& v)
{
    return v.size() * sizeof(T);
}
template <class O, class V>
std::size_t sizeBytes(const Ranged<O, V>& r)
{
    return sizeBytes(r.offset) + sizeBytes(r.values);
}

template <class T>
void shrinkArray(std::vector<T>& v)
{
    v.shrink_to_fit();
}
template <class O, class V>
void shrinkArray(const Ranged<O, V>& r)
{
    r.offset.shrink_to_fit();
    r.values.shrink_to_fit();
}

// Keep the entries whose flag is set, in order.
template <class T>
void keepFlagged(std::vector<T>& v, const std::vector<char>& keep)
{
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (keep[i]) v[out++] = v[i];
    v.resize(out);
}

// Keep the CSR ranges [offset[i], offset[i+1]) whose flag is set, in order.
template <class O, class V>
void keepFlagged(const Ranged<O, V>& r, const std::vector<char>& keep)
{
    std::vector<int> kept_offset(1, 0);
    std::remove_const_t<V> kept;
    for (std::size_t i = 0; i + 1 < r.offset.size(); ++i) {
        if (!keep[i]) continue;
        kept.insert(kept.end(), r.values.begin() + r.offset[i], r.values.begin() + r.offset[i + 1]);
        kept_offset.push_back(static_cast<int>(kept.size()));
    }
    r.offset = std::move(kept_offset);
    r.values = std::move(kept);
}

// ---- Group operations --------------------------------------------------------------------

// The capacity of the group's arrays with the flags With and none of Without [bytes].
template <unsigned With = 0u, unsigned Without = 0u, class Group>
std::size_t fieldBytes(const Group& g)
{
    std::size_t total = 0;
    forEachField<With, Without>([&](const auto&, const auto& array) { total += capacityBytes(array); }, g);
    return total;
}

template <class Group>
void shrinkFields(Group& g)
{
    forEachField<0u>([](const auto&, auto& array) { shrinkArray(array); }, g);
}

// n entities: per-entity arrays (with the flags With) resized, new entries value-initialised
// (zero); optional arrays stay empty while they are; CSR offsets start at {0}.
template <unsigned With = 0u, class Group>
void resizeFields(Group& g, std::size_t n)
{
    forEachField<With, notPerEntity>(
        [&](const auto& field, auto& array) {
            if constexpr ((flagsOf<decltype(field)> & optionalField) != 0u)
                if (array.empty()) return;
            array.resize(n);
        },
        g);
    forEachField<rangedField>(
        [](const auto&, auto& r) {
            if (r.offset.empty()) r.offset.assign(1, 0);
        },
        g);
}

// Keep the entities whose flag is set, in order (per-entity arrays and CSR children; the
// offsets into other groups and the pool are the caller's).
template <class Group>
void keepFlaggedFields(Group& g, const std::vector<char>& keep)
{
    forEachField<0u, childrenField | poolField>(
        [&](const auto& field, auto& array) {
            if constexpr ((flagsOf<decltype(field)> & optionalField) != 0u)
                if (array.empty()) return;
            keepFlagged(array, keep);
        },
        g);
}

// ---- Packing one entity (migration) --------------------------------------------------------
// The migrate arrays of entity i, as bytes: per-entity values in list order, each CSR
// child as a count and its entries; an optional array's value is packed (neutral when
// empty). unpackEntity appends the entity to a group (derived arrays get zeros, to be
// recomputed) and returns the position after it. Offsets into other groups and the pool
// are not packed: the owner of the relation packs the children (an interface its bonds).

namespace fieldDetail {

template <class T>
void put(std::vector<unsigned char>& out, const T& value)
{
    static_assert(std::is_trivially_copyable_v<T>, "packed values are copied as bytes");
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

template <class T>
T take(const std::vector<unsigned char>& in, std::size_t& at)
{
    T value;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

template <class T, unsigned Flags>
T neutralOf(const ArrayField<Flags>& field)
{
    if constexpr (std::is_arithmetic_v<T>)
        return static_cast<T>(field.neutral);
    else
        return T{};
}

}  // namespace fieldDetail

template <class Group>
void packEntity(const Group& g, int i, std::vector<unsigned char>& out)
{
    using fieldDetail::put;
    forEachField<migrateField, childrenField | poolField>(
        [&](const auto& field, const auto& array) {
            using Array = std::remove_cv_t<std::remove_reference_t<decltype(array)>>;
            if constexpr (fieldDetail::IsRanged<Array>::value) {
                const int first = array.offset[i], last = array.offset[i + 1];
                put(out, last - first);
                for (int k = first; k < last; ++k) put(out, array.values[k]);
            } else if constexpr ((flagsOf<decltype(field)> & optionalField) != 0u) {
                put(out,
                    array.empty() ? fieldDetail::neutralOf<typename Array::value_type>(field) : array[i]);
            } else {
                put(out, array[i]);
            }
        },
        g);
}

template <class Group>
std::size_t unpackEntity(Group& g, const std::vector<unsigned char>& in, std::size_t at)
{
    using fieldDetail::take;
    const std::size_t n = static_cast<std::size_t>(g.size());
    forEachField<0u, childrenField | poolField>(
        [&](const auto& field, auto& array) {
            constexpr unsigned flags = flagsOf<decltype(field)>;
            using Array = std::remove_cv_t<std::remove_reference_t<decltype(array)>>;
            if constexpr (fieldDetail::IsRanged<Array>::value) {
                using T =
                    typename std::remove_const_t<std::remove_reference_t<decltype(array.values)>>::value_type;
                if (array.offset.empty()) array.offset.assign(1, 0);
                const int count = (flags & migrateField) ? take<int>(in, at) : 0;
                for (int k = 0; k < count; ++k) array.values.push_back(take<T>(in, at));
                array.offset.push_back(static_cast<int>(array.values.size()));
            } else {
                using T = typename Array::value_type;
                const T value = (flags & migrateField) ? take<T>(in, at) : T{};
                if constexpr ((flags & optionalField) != 0u) {
                    static_assert(std::is_arithmetic_v<T>, "an optional array holds numbers");
                    const T neutral = fieldDetail::neutralOf<T>(field);
                    if (array.empty() && value == neutral) return;  // still all neutral: stays empty
                    if (array.empty()) array.assign(n, neutral);
                }
                array.push_back(value);
            }
        },
        g);
    return at;
}

}  // namespace rockfrac

// The array groups' field lists (dem/demFields.hpp, dem/demState.hpp): complete, naming
// the state file's entries, and packing one entity so that unpacking gives it back.
#include <catch2/catch.hpp>
#include <cstring>
#include <string>
#include <vector>

#include "boxMeshes.hpp"
#include "dem/demModel.hpp"

using namespace rockfrac;

namespace {

// The bytes of the arrays the field list visits (a CSR pair: both of its arrays).
template <class Group>
std::size_t listedBytes(const Group& g)
{
    std::size_t total = 0;
    forEachField<0u>(
        [&](const auto&, const auto& array) {
            using Array = std::decay_t<decltype(array)>;
            if constexpr (fieldDetail::IsRanged<Array>::value)
                total += sizeof(array.offset) + sizeof(array.values);
            else
                total += sizeof(array);
        },
        g);
    return total;
}

template <class Group>
std::vector<std::string> restartEntries(const Group& g)
{
    std::vector<std::string> names;
    forEachField<restartField>(
        [&](const auto& field, const auto&) { names.push_back(entryName<Group>(field)); }, g);
    return names;
}

template <class T>
bool sameBytes(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Entity i of `from` equals entity j of `to` in every migrate array (CSR children included).
template <class Group>
bool sameEntity(const Group& from, int i, const Group& to, int j)
{
    bool same = true;
    forEachField<migrateField, childrenField | poolField>(
        [&](const auto& field, const auto& a, const auto& b) {
            using Array = std::remove_cv_t<std::remove_reference_t<decltype(a)>>;
            if constexpr ((flagsOf<decltype(field)> & rangedField) != 0u) {
                const int n = a.offset[i + 1] - a.offset[i];
                same = same && b.offset[j + 1] - b.offset[j] == n;
                for (int k = 0; same && k < n; ++k)
                    same = sameBytes(a.values[a.offset[i] + k], b.values[b.offset[j] + k]);
            } else {
                using T = typename Array::value_type;
                const T neutral = fieldDetail::neutralOf<T>(field);
                same = same && sameBytes(a.empty() ? neutral : a[i], b.empty() ? neutral : b[j]);
            }
        },
        from, to);
    return same;
}

DemModel bondedBlock()
{
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    return DemModel(test::boxBlockMesh(3, 2, 2, {1e-3, 1e-3, 1e-3}, 1e-4), p);
}

}  // namespace

TEST_CASE("every array of a group is in its field list", "[demFields]")
{
    CHECK(listedBytes(CellArrays{}) == sizeof(CellArrays));
    CHECK(listedBytes(InterfaceArrays{}) == sizeof(InterfaceArrays));
    CHECK(listedBytes(BondStorage{}) == sizeof(BondStorage));
    CHECK(listedBytes(BondArrays{}) == sizeof(BondArrays));
    CHECK(listedBytes(ContactPairArrays{}) == sizeof(ContactPairArrays));
    CHECK(listedBytes(WallContactArrays{}) == sizeof(WallContactArrays));
}

TEST_CASE("the restart arrays are the state file's entries", "[demFields]")
{
    using Names = std::vector<std::string>;
    CHECK(restartEntries(CellArrays{}) == Names{"cell.position", "cell.velocity", "cell.orientation",
                                                "cell.angularVelocity", "cell.force", "cell.torque"});
    CHECK(restartEntries(BondArrays{}) == Names{"bond.stage", "bond.onsetDisplacement", "bond.onsetStress",
                                                "bond.ruptureDisplacement", "bond.maxDisplacement",
                                                "bond.damage"});
    CHECK(restartEntries(ContactPairArrays{}) == Names{"pair.cellA", "pair.cellB", "pair.interface",
                                                       "pair.tangentialSpring", "pair.lastNormal",
                                                       "pair.seat", "pair.status"});
    CHECK(restartEntries(WallContactArrays{}) == Names{"wallItem.cell", "wallItem.wall",
                                                       "wallItem.tangentialSpring", "wallItem.lastNormal",
                                                       "wallItem.status"});
    // The compact bond storage goes to the file through BondArrays (DemModel::bonds()).
    CHECK(restartEntries(BondStorage{}).empty());
}

TEST_CASE("a packed cell unpacks to the same cell", "[demFields]")
{
    const DemModel model = bondedBlock();
    const CellArrays& cells = model.cells();
    std::vector<unsigned char> buffer;
    for (int c : {4, 1, 9}) packEntity(cells, c, buffer);

    CellArrays copy;
    std::size_t at = 0;
    for (int k = 0; k < 3; ++k) at = unpackEntity(copy, buffer, at);
    CHECK(at == buffer.size());
    REQUIRE(copy.size() == 3);
    CHECK(sameEntity(cells, 4, copy, 0));
    CHECK(sameEntity(cells, 1, copy, 1));
    CHECK(sameEntity(cells, 9, copy, 2));
    CHECK(copy.core_vertex_offset.size() == 4);
    CHECK(copy.anchor_node_offset.back() == static_cast<int>(copy.anchor_nodes.size()));
    // Derived arrays are not packed: sized with the cell, to be recomputed.
    CHECK(copy.force.size() == 3);
    CHECK(copy.force[1] == Vec3{});
}

TEST_CASE("an optional array stays empty while every unpacked value is neutral", "[demFields]")
{
    DemModel model = bondedBlock();
    REQUIRE(model.interfaces().size() >= 3);
    std::vector<unsigned char> plain, scaled;
    packEntity(model.interfaces(), 0, plain);
    model.scaleInterfaceStrength(2, 0.5);
    const InterfaceArrays& f = model.interfaces();
    packEntity(f, 0, scaled);
    packEntity(f, 2, scaled);

    InterfaceArrays copy;
    unpackEntity(copy, plain, 0);
    CHECK(copy.strength_scale.empty());  // the model had no scale when packed
    CHECK(sameEntity(f, 0, copy, 0));
    std::size_t at = unpackEntity(copy, scaled, 0);
    unpackEntity(copy, scaled, at);
    REQUIRE(copy.strength_scale.size() == 3);  // filled with the neutral 1 at the first scaled one
    CHECK(copy.strength_scale == std::vector<double>{1.0, 1.0, 0.5});
    CHECK(sameEntity(f, 2, copy, 2));
    CHECK(copy.softening_slot.empty());  // the pool is the interface owner's to pack
}

TEST_CASE("memoryUse counts every array of the groups", "[demFields]")
{
    const DemModel model = bondedBlock();
    const DemMemoryBytes m = model.memoryUse();
    CHECK(m.interfaces == fieldBytes(model.interfaces()));
    CHECK(m.bonds + m.softening == fieldBytes(model.bondStorage()));
    CHECK(m.pairs == fieldBytes(model.contactPairs()));
    CHECK(m.cores + m.anchor_nodes == fieldBytes<rangedField>(model.cells()));
    CHECK(m.cells > fieldBytes<0u, rangedField>(model.cells()));  // with the per-cell caches
    CHECK(m.total() >= fieldBytes(model.cells()) + fieldBytes(model.wallContacts()) + m.interfaces + m.pairs);
}

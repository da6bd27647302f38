// bondedDemFoam case: the whole-state restart file <time>/demState.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "demCase/demCase.hpp"
#include "io/stateFile.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

// ---- Whole state ------------------------------------------------------------------

namespace {

// One array in the state file's types: doubles (quaternions as w, x, y, z), int64, bytes.
void putArray(StateFile& s, const std::string& name, const std::vector<Vec3>& v)
{
    s.put(name, v);
}
void putArray(StateFile& s, const std::string& name, const std::vector<double>& v)
{
    s.put(name, v);
}
void putArray(StateFile& s, const std::string& name, const std::vector<Quat>& q)
{
    std::vector<double> flat;
    flat.reserve(4 * q.size());
    for (const auto& v : q) flat.insert(flat.end(), {v.w, v.x, v.y, v.z});
    s.put(name, flat);
}
void putArray(StateFile& s, const std::string& name, const std::vector<int>& v)
{
    s.put(name, std::vector<std::int64_t>(v.begin(), v.end()));
}
void putArray(StateFile& s, const std::string& name, const std::vector<unsigned char>& v)
{
    s.put(name, std::vector<std::uint8_t>(v.begin(), v.end()));
}

// count < 0: any length.
void getArray(const StateFile& s, const std::string& name, long count, std::vector<Vec3>& v)
{
    v = s.vectors(name, count);
}
void getArray(const StateFile& s, const std::string& name, long count, std::vector<double>& v)
{
    v = s.doubles(name, count);
}
void getArray(const StateFile& s, const std::string& name, long count, std::vector<Quat>& q)
{
    const auto& flat = s.doubles(name, count < 0 ? -1 : 4 * count);
    q.resize(flat.size() / 4);
    for (std::size_t c = 0; c < q.size(); ++c)
        q[c] = {flat[4 * c], flat[4 * c + 1], flat[4 * c + 2], flat[4 * c + 3]};
}
void getArray(const StateFile& s, const std::string& name, long count, std::vector<int>& v)
{
    const auto& wide = s.integers(name, count);
    v.assign(wide.begin(), wide.end());
}
void getArray(const StateFile& s, const std::string& name, long count, std::vector<unsigned char>& v)
{
    const auto& bytes = s.bytes(name, count);
    v.assign(bytes.begin(), bytes.end());
}

// The group's restart arrays as "<entity>.<name>" (an empty optional array is not written).
template <class Group>
void putFields(StateFile& s, const Group& g)
{
    forEachField<restartField>(
        [&](const auto& field, const auto& array) {
            if constexpr ((flagsOf<decltype(field)> & optionalField) != 0u)
                if (array.empty()) return;
            putArray(s, entryName<Group>(field), array);
        },
        g);
}

// The group's restart arrays, count entries each (count < 0: as many as the first has).
// Missing from the file: an optional array is neutral everywhere, a derived one stays
// empty (recomputed; states written before it was kept), any other is an error.
template <class Group>
void getFields(const StateFile& s, Group& g, long count)
{
    forEachField<restartField>(
        [&](const auto& field, auto& array) {
            constexpr unsigned flags = flagsOf<decltype(field)>;
            const std::string name = entryName<Group>(field);
            if constexpr ((flags & optionalField) != 0u) {
                if (!s.has(name)) {
                    array.assign(static_cast<std::size_t>(std::max(count, 0L)), field.neutral);
                    return;
                }
            }
            if ((flags & derivedField) && !s.has(name)) return;
            getArray(s, name, count, array);
            if (count < 0) count = static_cast<long>(array.size());
        },
        g);
}

std::vector<double> energyArray(const DemEnergies& e)
{
    return {e.kinetic_translation, e.kinetic_rotation, e.bond_strain, e.contact_elastic, e.bond_damping,
            e.contact_damping,     e.friction,         e.fracture,    e.wall_work,       e.gravity_work};
}

DemEnergies energiesFrom(const std::vector<double>& a)
{
    DemEnergies e;
    e.kinetic_translation = a[0];
    e.kinetic_rotation = a[1];
    e.bond_strain = a[2];
    e.contact_elastic = a[3];
    e.bond_damping = a[4];
    e.contact_damping = a[5];
    e.friction = a[6];
    e.fracture = a[7];
    e.wall_work = a[8];
    e.gravity_work = a[9];
    return e;
}

}  // namespace

void writeDemState(const fs::path& file, const DemModel& model, long step, double peakForce,
                   bool loadingStarted)
{
    StateFile s;
    // The restart arrays of each group (demState.hpp): the cells' state and the forces of
    // the last step (the continued run starts its next step with them, as the
    // uninterrupted run does, instead of re-evaluating the dashpots at the end-of-step
    // velocities), the bonds' histories, the contact histories and their keys.
    putFields(s, model.cells());
    putFields(s, model.bonds());
    putFields(s, model.contactPairs());
    putFields(s, model.wallContacts());

    std::vector<double> walls;
    for (int k = 0; k < model.nWalls(); ++k) {
        const WallState& ws = model.wall(k);
        walls.insert(walls.end(), {ws.origin.x, ws.origin.y, ws.origin.z, ws.orientation.w, ws.orientation.x,
                                   ws.orientation.y, ws.orientation.z, ws.velocity.x, ws.velocity.y,
                                   ws.velocity.z, ws.angular_velocity.x, ws.angular_velocity.y,
                                   ws.angular_velocity.z, ws.initial_origin.x, ws.initial_origin.y,
                                   ws.initial_origin.z, ws.reaction.x, ws.reaction.y, ws.reaction.z});
    }
    s.put("walls", walls);
    s.put("energies", energyArray(model.energies()));
    s.putScalar("energyExchanged", model.energies().exchanged);
    // The powers the next step books over its first half kick (DemModel::step).
    std::vector<double> rates{model.forceRates().bond_damping, model.forceRates().contact_damping};
    for (int k = 0; k < model.nWalls(); ++k) rates.push_back(model.wallPower(k));
    s.put("forceRates", rates);
    s.putScalar("initialBalance", model.initialBalance());
    s.putScalar("contactFrequencyBound", model.contactFrequencyBound());  // the step check
    s.putScalar("time", model.time());
    s.put("step", std::vector<std::int64_t>{step});
    s.putScalar("peakForce", peakForce);
    s.put("loadingStarted", std::vector<std::uint8_t>{static_cast<std::uint8_t>(loadingStarted)});
    s.write(file);
}

DemRestart readDemState(const fs::path& file, DemModel& model)
{
    const StateFile s = StateFile::read(file);
    const long nCells = model.cells().size();
    CellArrays cells;
    getFields(s, cells, nCells);
    model.setCellState(cells);

    BondArrays b = model.bonds();
    getFields(s, b, model.nBonds());
    model.setBondHistory(b);

    // States of point-contact runs, and those written before 2026-12-03, have no seats:
    // every pair starts unseated (the optional array's neutral value).
    ContactPairArrays p;
    getFields(s, p, -1);
    const long nPairs = p.size();
    for (long k = 0; k < nPairs; ++k)
        if (p.cell_a[k] < 0 || p.cell_a[k] >= nCells || p.cell_b[k] < 0 || p.cell_b[k] >= nCells)
            throw UserError(file.string() + ": contact pair " + std::to_string(k) +
                            " names a cell outside the mesh; the state does not belong to this case");
    WallContactArrays w;
    getFields(s, w, -1);
    const long nItems = w.size();
    for (long k = 0; k < nItems; ++k)
        if (w.cell[k] < 0 || w.cell[k] >= nCells || w.wall[k] < 0 || w.wall[k] >= model.nWalls())
            throw UserError(file.string() + ": wall contact " + std::to_string(k) +
                            " names a cell or wall outside the case; the state does not belong to this case");
    model.setContactHistory(p, w);

    const auto& walls = s.doubles("walls", 19L * model.nWalls());
    for (int k = 0; k < model.nWalls(); ++k) {
        WallState ws = model.wall(k);
        const double* a = walls.data() + 19 * k;
        ws.origin = {a[0], a[1], a[2]};
        ws.orientation = {a[3], a[4], a[5], a[6]};
        ws.velocity = {a[7], a[8], a[9]};
        ws.angular_velocity = {a[10], a[11], a[12]};
        ws.initial_origin = {a[13], a[14], a[15]};
        ws.reaction = {a[16], a[17], a[18]};
        model.setWallState(k, ws);
    }
    // States written before 2026-12-02 have no powers: the first half kick after the
    // restart then books none (the energy columns differ from an uninterrupted run there).
    if (s.has("forceRates")) {
        const auto& rates = s.doubles("forceRates", 2L + model.nWalls());
        model.setForceRates({rates[0], rates[1]});
        for (int k = 0; k < model.nWalls(); ++k) {
            WallState ws = model.wall(k);
            ws.power = rates[2 + k];
            model.setWallState(k, ws);
        }
    }
    DemRestart r;
    r.step = s.integers("step", 1)[0];
    r.time = s.scalar("time");
    r.peakForce = s.scalar("peakForce");
    r.loadingStarted = s.bytes("loadingStarted", 1)[0] != 0;
    DemEnergies energies = energiesFrom(s.doubles("energies", 10));
    if (s.has("energyExchanged")) energies.exchanged = s.scalar("energyExchanged");
    model.setClock(r.time, r.step, energies, s.scalar("initialBalance"));
    // Last, as setCellForces marks the forces valid (states written before 2026-12
    // have none: the first step then re-evaluates them).
    model.setCellForces(cells);
    if (s.has("contactFrequencyBound")) model.setContactFrequencyBound(s.scalar("contactFrequencyBound"));
    return r;
}

}  // namespace rockfrac

// bondedDemFoam case: the whole-state restart file <time>/demState.
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

std::vector<double> quats(const std::vector<Quat>& q)
{
    std::vector<double> flat;
    flat.reserve(4 * q.size());
    for (const auto& v : q) flat.insert(flat.end(), {v.w, v.x, v.y, v.z});
    return flat;
}

template <class T>
std::vector<std::int64_t> toInt64(const std::vector<T>& v)
{
    return std::vector<std::int64_t>(v.begin(), v.end());
}

template <class T>
std::vector<T> fromInt64(const std::vector<std::int64_t>& v)
{
    return std::vector<T>(v.begin(), v.end());
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
    const CellArrays& cells = model.cells();
    s.put("cell.position", cells.position);
    s.put("cell.velocity", cells.velocity);
    s.put("cell.orientation", quats(cells.orientation));
    s.put("cell.angularVelocity", cells.angular_velocity);
    // The forces of the last step: the continued run starts its next step with them,
    // as the uninterrupted run does, instead of re-evaluating the dashpots at the
    // end-of-step velocities (which would make the continuation differ).
    s.put("cell.force", cells.force);
    s.put("cell.torque", cells.torque);

    const BondArrays& b = model.bonds();
    s.put("bond.stage", std::vector<std::uint8_t>(b.stage.begin(), b.stage.end()));
    s.put("bond.onsetDisplacement", b.onset_displacement);
    s.put("bond.onsetStress", b.onset_stress);
    s.put("bond.ruptureDisplacement", b.rupture_displacement);
    s.put("bond.maxDisplacement", b.max_displacement);
    s.put("bond.damage", b.damage);

    const ContactPairArrays& p = model.contactPairs();
    s.put("pair.cellA", toInt64(p.cell_a));
    s.put("pair.cellB", toInt64(p.cell_b));
    s.put("pair.interface", toInt64(p.interface));
    s.put("pair.tangentialSpring", p.tangential_spring);
    s.put("pair.lastNormal", p.last_normal);
    if (!p.seat.empty()) s.put("pair.seat", p.seat);  // patch contacts only
    s.put("pair.status", std::vector<std::uint8_t>(p.status.begin(), p.status.end()));

    const WallContactArrays& w = model.wallContacts();
    s.put("wallItem.cell", toInt64(w.cell));
    s.put("wallItem.wall", toInt64(w.wall));
    s.put("wallItem.tangentialSpring", w.tangential_spring);
    s.put("wallItem.lastNormal", w.last_normal);
    s.put("wallItem.status", std::vector<std::uint8_t>(w.status.begin(), w.status.end()));

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
    std::vector<Quat> orientation(nCells);
    const auto& q = s.doubles("cell.orientation", 4 * nCells);
    for (long c = 0; c < nCells; ++c) orientation[c] = {q[4 * c], q[4 * c + 1], q[4 * c + 2], q[4 * c + 3]};
    model.setCellState(s.vectors("cell.position", nCells), s.vectors("cell.velocity", nCells), orientation,
                       s.vectors("cell.angularVelocity", nCells));

    const long nBonds = model.nBonds();
    BondArrays b = model.bonds();
    const auto& stage = s.bytes("bond.stage", nBonds);
    b.stage.assign(stage.begin(), stage.end());
    b.onset_displacement = s.doubles("bond.onsetDisplacement", nBonds);
    b.onset_stress = s.doubles("bond.onsetStress", nBonds);
    b.rupture_displacement = s.doubles("bond.ruptureDisplacement", nBonds);
    b.max_displacement = s.doubles("bond.maxDisplacement", nBonds);
    b.damage = s.doubles("bond.damage", nBonds);
    model.setBondHistory(b);

    ContactPairArrays p;
    p.cell_a = fromInt64<int>(s.integers("pair.cellA"));
    const long nPairs = static_cast<long>(p.cell_a.size());
    p.cell_b = fromInt64<int>(s.integers("pair.cellB", nPairs));
    p.interface = fromInt64<int>(s.integers("pair.interface", nPairs));
    p.tangential_spring = s.vectors("pair.tangentialSpring", nPairs);
    p.last_normal = s.vectors("pair.lastNormal", nPairs);
    // States of point-contact runs, and those written before 2026-12-03, have no seats:
    // every pair starts unseated.
    p.seat = s.has("pair.seat") ? s.doubles("pair.seat", nPairs) : std::vector<double>(nPairs, -1.0);
    const auto& pairStatus = s.bytes("pair.status", nPairs);
    p.status.assign(pairStatus.begin(), pairStatus.end());
    for (long k = 0; k < nPairs; ++k)
        if (p.cell_a[k] < 0 || p.cell_a[k] >= nCells || p.cell_b[k] < 0 || p.cell_b[k] >= nCells)
            throw UserError(file.string() + ": contact pair " + std::to_string(k) +
                            " names a cell outside the mesh; the state does not belong to this case");
    WallContactArrays w;
    w.cell = fromInt64<int>(s.integers("wallItem.cell"));
    const long nItems = static_cast<long>(w.cell.size());
    w.wall = fromInt64<int>(s.integers("wallItem.wall", nItems));
    w.tangential_spring = s.vectors("wallItem.tangentialSpring", nItems);
    w.last_normal = s.vectors("wallItem.lastNormal", nItems);
    const auto& itemStatus = s.bytes("wallItem.status", nItems);
    w.status.assign(itemStatus.begin(), itemStatus.end());
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
    if (s.has("cell.force"))
        model.setCellForces(s.vectors("cell.force", nCells), s.vectors("cell.torque", nCells));
    if (s.has("contactFrequencyBound")) model.setContactFrequencyBound(s.scalar("contactFrequencyBound"));
    return r;
}

}  // namespace rockfrac

#include "crusher/crusherState.hpp"

#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "io/stateFile.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

// ---- The record of the feed -------------------------------------------------------

void FeedRecord::add(const InsertedRock& rock)
{
    const int ordinal = static_cast<int>(rocks.size());
    rocks.push_back({rock.index, rock.feed_class, rock.mesh.nCells(), rock.size, rock.pose});
    for (int local = 0; local < rock.mesh.nCells(); ++local) {
        cell_rock.push_back(ordinal);
        cell_local.push_back(local);
    }
}

void FeedRecord::compact(const std::vector<int>& new_index)
{
    std::size_t kept = 0;
    for (std::size_t c = 0; c < new_index.size() && c < cell_rock.size(); ++c) {
        if (new_index[c] < 0) continue;
        cell_rock[kept] = cell_rock[c];
        cell_local[kept] = cell_local[c];
        ++kept;
    }
    cell_rock.resize(kept);
    cell_local.resize(kept);
}

// ---- The file ---------------------------------------------------------------------

namespace {

std::vector<std::int64_t> wide(const std::vector<int>& v)
{
    return {v.begin(), v.end()};
}

std::vector<int> narrow(const std::vector<std::int64_t>& v)
{
    return {v.begin(), v.end()};
}

void putRocks(StateFile& s, const std::vector<FedRock>& rocks)
{
    std::vector<std::int64_t> index, feedClass, cells;
    std::vector<double> size, orientation;
    std::vector<Vec3> translation, velocity, angularVelocity;
    for (const FedRock& r : rocks) {
        index.push_back(r.index);
        feedClass.push_back(r.feed_class);
        cells.push_back(r.n_cells);
        size.push_back(r.size);
        translation.push_back(r.pose.translation);
        const Quat& q = r.pose.orientation;
        orientation.insert(orientation.end(), {q.w, q.x, q.y, q.z});
        velocity.push_back(r.pose.velocity);
        angularVelocity.push_back(r.pose.angular_velocity);
    }
    s.put("rocks.index", index);
    s.put("rocks.class", feedClass);
    s.put("rocks.cells", cells);
    s.put("rocks.size", size);
    s.put("rocks.translation", translation);
    s.put("rocks.orientation", orientation);
    s.put("rocks.velocity", velocity);
    s.put("rocks.angularVelocity", angularVelocity);
}

std::vector<FedRock> getRocks(const StateFile& s)
{
    const auto& index = s.integers("rocks.index");
    const long n = static_cast<long>(index.size());
    const auto& feedClass = s.integers("rocks.class", n);
    const auto& cells = s.integers("rocks.cells", n);
    const auto& size = s.doubles("rocks.size", n);
    const std::vector<Vec3> translation = s.vectors("rocks.translation", n);
    const auto& orientation = s.doubles("rocks.orientation", 4 * n);
    const std::vector<Vec3> velocity = s.vectors("rocks.velocity", n);
    const std::vector<Vec3> angularVelocity = s.vectors("rocks.angularVelocity", n);
    std::vector<FedRock> rocks(n);
    for (long k = 0; k < n; ++k) {
        FedRock& r = rocks[k];
        r.index = static_cast<int>(index[k]);
        r.feed_class = static_cast<int>(feedClass[k]);
        r.n_cells = static_cast<int>(cells[k]);
        r.size = size[k];
        r.pose.translation = translation[k];
        r.pose.orientation = {orientation[4 * k], orientation[4 * k + 1], orientation[4 * k + 2],
                              orientation[4 * k + 3]};
        r.pose.velocity = velocity[k];
        r.pose.angular_velocity = angularVelocity[k];
    }
    return rocks;
}

}  // namespace

void writeCrusherState(const fs::path& file, const CrusherState& c)
{
    StateFile s;
    s.put("step", std::vector<std::int64_t>{c.step});
    s.putScalar("time", c.time);
    putRocks(s, c.fed.rocks);
    s.put("cells.rock", wide(c.fed.cell_rock));
    s.put("cells.localCell", wide(c.fed.cell_local));
    s.putScalar("feed.massFed", c.mass_fed);
    s.put("feed.rocksFed", std::vector<std::int64_t>{c.rocks_fed});
    s.put("feed.rocksFedByClass", wide(c.rocks_fed_by_class));
    s.put("feed.attemptsSpent", std::vector<std::int64_t>{c.attempts_spent});
    s.putScalar("discharge.mass", c.mass_discharged);
    s.put("discharge.fragments", std::vector<std::int64_t>{c.fragments_discharged});
    s.put("walls.work", c.wall_work);
    s.put("spin",
          std::vector<double>{c.spin_angle, c.spin_rate, c.spin_torque_work, c.spin_bearing_dissipated});
    s.put("chokeLowered", std::vector<std::uint8_t>{static_cast<std::uint8_t>(c.choke_lowered)});
    s.put("window.sumForce", std::vector<Vec3>{c.sum_force});
    s.put("window.sumTorque", std::vector<Vec3>{c.sum_torque});
    s.put("window.sums", std::vector<double>{c.sum_power, c.last_power});
    s.put("window.steps", std::vector<std::int64_t>{c.sample_steps});
    s.put("counters",
          std::vector<std::int64_t>{c.split_steps, c.substeps, c.most_substeps, c.neighbour_rebuilds});
    s.write(file);
}

CrusherState readCrusherState(const fs::path& file)
{
    const StateFile s = StateFile::read(file);
    CrusherState c;
    c.step = s.integers("step", 1)[0];
    c.time = s.scalar("time");
    c.fed.rocks = getRocks(s);
    c.fed.cell_rock = narrow(s.integers("cells.rock"));
    c.fed.cell_local = narrow(s.integers("cells.localCell", static_cast<long>(c.fed.cell_rock.size())));
    c.mass_fed = s.scalar("feed.massFed");
    c.rocks_fed = static_cast<int>(s.integers("feed.rocksFed", 1)[0]);
    c.rocks_fed_by_class = narrow(s.integers("feed.rocksFedByClass"));
    c.attempts_spent = s.integers("feed.attemptsSpent", 1)[0];
    c.mass_discharged = s.scalar("discharge.mass");
    c.fragments_discharged = static_cast<int>(s.integers("discharge.fragments", 1)[0]);
    c.wall_work = s.doubles("walls.work");
    const auto& spin = s.doubles("spin", 4);
    c.spin_angle = spin[0];
    c.spin_rate = spin[1];
    c.spin_torque_work = spin[2];
    c.spin_bearing_dissipated = spin[3];
    c.choke_lowered = s.bytes("chokeLowered", 1)[0] != 0;
    c.sum_force = s.vectors("window.sumForce", 1)[0];
    c.sum_torque = s.vectors("window.sumTorque", 1)[0];
    const auto& sums = s.doubles("window.sums", 2);
    c.sum_power = sums[0];
    c.last_power = sums[1];
    c.sample_steps = s.integers("window.steps", 1)[0];
    const auto& counters = s.integers("counters", 4);
    c.split_steps = counters[0];
    c.substeps = counters[1];
    c.most_substeps = static_cast<int>(counters[2]);
    c.neighbour_rebuilds = counters[3];
    if (c.rocks_fed != static_cast<int>(c.fed.rocks.size()))
        throw UserError(file.string() + ": feed.rocksFed " + std::to_string(c.rocks_fed) + " but " +
                        std::to_string(c.fed.rocks.size()) + " rocks recorded; the file is inconsistent");
    return c;
}

// ---- Shapes and the model ---------------------------------------------------------

void appendShapes(CellShapes& s, const InsertedRock& rock, const DemModel& model)
{
    if (s.cellVertexOffset.empty()) s.cellVertexOffset.assign(1, 0);
    if (s.cellFaceOffset.empty()) s.cellFaceOffset.assign(1, 0);
    if (s.faceVertexOffset.empty()) s.faceVertexOffset.assign(1, 0);
    const VoronoiMesh& m = rock.mesh;
    const Mat3 pose = rotationMatrix(rock.pose.orientation);
    const CellArrays& cells = model.cells();
    for (int local = 0; local < m.nCells(); ++local) {
        const int c = rock.first_cell + local;
        const Mat3 R = rotationMatrix(cells.orientation[c]);
        const int vertex_base = s.cellVertexOffset.back();
        for (int v = m.cellVertexOffset[local]; v < m.cellVertexOffset[local + 1]; ++v)
            s.bodyVertices.push_back(
                transposeTimes(R, rock.pose.translation + pose * m.vertices[v] - cells.position[c]));
        s.cellVertexOffset.push_back(static_cast<int>(s.bodyVertices.size()));
        for (int f = m.cellFaceOffset[local]; f < m.cellFaceOffset[local + 1]; ++f) {
            for (int k = m.faceVertexOffset[f]; k < m.faceVertexOffset[f + 1]; ++k)
                s.faceVertices.push_back(vertex_base + m.faceVertices[k]);
            s.faceVertexOffset.push_back(static_cast<int>(s.faceVertices.size()));
        }
        s.cellFaceOffset.push_back(static_cast<int>(s.faceVertexOffset.size()) - 1);
    }
}

void compactShapes(CellShapes& s, const std::vector<int>& new_index)
{
    CellShapes out;
    out.cellVertexOffset.assign(1, 0);
    out.cellFaceOffset.assign(1, 0);
    out.faceVertexOffset.assign(1, 0);
    for (std::size_t c = 0; c < new_index.size(); ++c) {
        if (new_index[c] < 0) continue;
        const int old_base = s.cellVertexOffset[c], new_base = out.cellVertexOffset.back();
        out.bodyVertices.insert(out.bodyVertices.end(), s.bodyVertices.begin() + old_base,
                                s.bodyVertices.begin() + s.cellVertexOffset[c + 1]);
        out.cellVertexOffset.push_back(static_cast<int>(out.bodyVertices.size()));
        for (int f = s.cellFaceOffset[c]; f < s.cellFaceOffset[c + 1]; ++f) {
            for (int k = s.faceVertexOffset[f]; k < s.faceVertexOffset[f + 1]; ++k)
                out.faceVertices.push_back(s.faceVertices[k] - old_base + new_base);
            out.faceVertexOffset.push_back(static_cast<int>(out.faceVertices.size()));
        }
        out.cellFaceOffset.push_back(static_cast<int>(out.faceVertexOffset.size()) - 1);
    }
    s = std::move(out);
}

void rebuildCrusherModel(const FeedRecord& fed, const FeedFactory& factory, DemModel& model,
                         CellShapes& shapes, const fs::path& file)
{
    const auto mismatch = [&](const std::string& what) {
        return UserError(file.string() + ": " + what +
                         "; the state does not belong to this case's feed (constant/loading feed, its "
                         "template rocks)");
    };
    // Where each rock's cells begin among all the cells ever fed.
    std::vector<long> first(fed.rocks.size() + 1, 0);
    for (std::size_t k = 0; k < fed.rocks.size(); ++k) {
        const FedRock& r = fed.rocks[k];
        if (r.feed_class < 0 || r.feed_class >= factory.classes())
            throw mismatch("rock " + std::to_string(r.index) + " is of size class " +
                           std::to_string(r.feed_class) + ", the feed has " +
                           std::to_string(factory.classes()));
        const FeedRockTemplate& from = factory.rock(r.feed_class);
        if (r.n_cells != from.mesh.nCells() || !(r.size > 0.0))
            throw mismatch("rock " + std::to_string(r.index) + " has " + std::to_string(r.n_cells) +
                           " cells, its template " + std::to_string(from.mesh.nCells()));
        // As FeedFactory::feed inserts it.
        InsertedRock rock;
        rock.index = r.index;
        rock.feed_class = r.feed_class;
        rock.size = r.size;
        rock.mesh = scaleVoronoiMesh(from.mesh, r.size / from.sieve_size, {});
        rock.pose = r.pose;
        rock.first_cell = model.insertCells(rock.mesh, rock.pose);
        appendShapes(shapes, rock, model);
        first[k + 1] = first[k] + r.n_cells;
    }
    // The cells there are, in the model's order (increasing: removing cells keeps the order).
    std::vector<char> remove(static_cast<std::size_t>(model.cells().size()), 1);
    long last = -1;
    for (std::size_t c = 0; c < fed.cell_rock.size(); ++c) {
        const int k = fed.cell_rock[c], local = fed.cell_local[c];
        if (k < 0 || k >= static_cast<int>(fed.rocks.size()) || local < 0 || local >= fed.rocks[k].n_cells)
            throw mismatch("cell " + std::to_string(c) + " names rock " + std::to_string(k) + " cell " +
                           std::to_string(local) + ", which was not fed");
        const long at = first[k] + local;
        if (at <= last) throw mismatch("cell " + std::to_string(c) + " is out of the feed's order");
        remove[at] = 0;
        last = at;
    }
    const std::vector<int> new_index = model.removeCellsOnly(remove);
    compactShapes(shapes, new_index);
}

}  // namespace rockfrac

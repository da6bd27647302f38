#include "crusher/feedCells.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

#include "dem/bondLaw.hpp"
#include "fragments/fragments.hpp"

namespace rockfrac {

CellSizes templateCellSizes(const FeedRockTemplate& rock, double density)
{
    // Every bond broken: each cell its own fragment, in cell order (fragments are numbered by
    // their smallest cell).
    CellPoses poses;
    poses.position = rock.mesh.centroids;
    poses.orientation = initialCellOrientations(rock.mesh, density);
    const FragmentAnalysis a = analyseFragments(rock.mesh, demBondCells(rock.mesh),
                                                std::vector<std::uint8_t>(rock.mesh.nBonds(), bondBroken),
                                                poses, poses.orientation, density);
    CellSizes c;
    for (const Fragment& f : a.fragments) {
        c.sieve_size.push_back(f.sieve_size);
        c.mass.push_back(f.mass);
    }
    return c;
}

CellSizes fedCellSizes(const std::vector<FedRock>& rocks, const std::vector<FeedRockTemplate>& templates,
                       const std::vector<CellSizes>& per_class)
{
    CellSizes all;
    for (const FedRock& rock : rocks) {
        const auto k = static_cast<std::size_t>(rock.feed_class);
        if (rock.feed_class < 0 || k >= templates.size() || k >= per_class.size())
            throw std::invalid_argument("fedCellSizes: rock " + std::to_string(rock.index) + " of class " +
                                        std::to_string(rock.feed_class) + " has no template");
        const CellSizes& cells = per_class[k];
        if (static_cast<int>(cells.mass.size()) != rock.n_cells)
            throw std::invalid_argument("fedCellSizes: rock " + std::to_string(rock.index) + " has " +
                                        std::to_string(rock.n_cells) + " cells, its template " +
                                        std::to_string(cells.mass.size()));
        const double s = rock.size / templates[k].sieve_size;
        for (std::size_t c = 0; c < cells.mass.size(); ++c) {
            all.sieve_size.push_back(s * cells.sieve_size[c]);
            all.mass.push_back(s * s * s * cells.mass[c]);
        }
    }
    return all;
}

}  // namespace rockfrac

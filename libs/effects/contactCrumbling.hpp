#pragma once
// Contact crumbling — the effect the paper names (section 6) for the bonded DEM
// being too stiff and too strong on irregular rocks.
//
// Under a steel plate real rock is crushed into fines long before the specimen
// splits: the contact flattens, the load spreads, and the force–displacement
// curve starts soft and stiffens as the crushed zone consolidates. Cells of a
// coarse Voronoi mesh are rigid and centimetre-sized; they cannot crumble. This
// effect weakens the rock where it would: every interface whose bond points lie
// (on average) within `depth` of a plate at the start keeps only
// (1 - strengthLoss) of its tensile strength and cohesion. Those bonds fail early,
// the cells at the contact rearrange, the contact flattens; the rest of the
// specimen is untouched. strengthLoss = 0 is the baseline model exactly.
#include <algorithm>
#include <sstream>

#include "core/dictionary.hpp"
#include "dem/demModel.hpp"
#include "dem/quat.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class ContactCrumbling final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;

    explicit ContactCrumbling(const Dictionary& d)
        : strength_loss_(d.getScalar("strengthLoss", Bounds::closed(0.0, 0.95))),
          depth_(d.getScalar("depth", Bounds::positive()))
    {
    }

    void applyToModel(DemModel& model, const EffectContext& context) const override
    {
        if (strength_loss_ == 0.0) return;
        const CellArrays& cells = model.cells();
        const InterfaceArrays& interfaces = model.interfaces();
        const BondArrays& bonds = model.bonds();
        for (int k = 0; k < interfaces.size(); ++k) {
            const int ci = interfaces.cell_i[k];
            const Mat3 Ri = rotationMatrix(cells.orientation[ci]);
            double z = 0.0;
            const int first = interfaces.bond_offset[k], last = interfaces.bond_offset[k + 1];
            for (int b = first; b < last; ++b) z += (cells.position[ci] + Ri * bonds.anchor_i[b]).z;
            z /= static_cast<double>(last - first > 0 ? last - first : 1);
            const double distance = std::min(z - context.lowerPlateZ, context.upperPlateZ - z);
            if (distance < depth_) model.scaleInterfaceStrength(k, 1.0 - strength_loss_);
        }
    }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "contactCrumbling: bonds within " << 1e3 * depth_ << " mm of a plate keep "
          << 100 * (1 - strength_loss_) << " % of their strength";
        return s.str();
    }

private:
    double strength_loss_, depth_;
};

}  // namespace rockfrac

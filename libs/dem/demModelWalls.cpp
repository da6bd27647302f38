// DemModel: rigid walls (plates and triangulated surfaces), their motion and poses.
#include <algorithm>
#include <cstdint>

#include "core/error.hpp"
#include "dem/demModel.hpp"
#include "dem/surfaceFeatures.hpp"

namespace rockfrac {

int DemModel::addPlate(const Vec3& point, const Vec3& normal_into_domain, const Vec3& velocity)
{
    if (!(norm(normal_into_domain) > 0.0)) throw UserError("a plate needs a non-zero normal");
    WallState w;
    w.kind = wallPlate;
    w.origin = w.initial_origin = point;
    w.normal = normalised(normal_into_domain);
    w.velocity = velocity;
    walls_.push_back(w);
    wall_extent_.push_back(0.0);
    triangle_grids_.emplace_back();
    lists_valid_ = forces_valid_ = false;
    return nWalls() - 1;
}

int DemModel::addTriSurface(const std::vector<Vec3>& vertices,
                            const std::vector<std::array<int, 3>>& triangles, const WallMotion& motion)
{
    if (triangles.empty()) throw UserError("a triangulated wall needs at least one triangle");
    WallState w;
    w.kind = wallTriSurface;
    w.first_triangle = static_cast<int>(triangle_vertices_.size() / 3);
    w.n_triangles = static_cast<int>(triangles.size());
    std::vector<Vec3> local;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            if (t[k] < 0 || t[k] >= static_cast<int>(vertices.size()))
                throw UserError("a triangle of a wall refers to a vertex that does not exist");
            local.push_back(vertices[t[k]]);
        }
    triangle_vertices_.insert(triangle_vertices_.end(), local.begin(), local.end());
    const std::vector<std::uint16_t> features = surfaceFeatureFlags(vertices, triangles);
    triangle_features_.insert(triangle_features_.end(), features.begin(), features.end());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        triangle_prisms_.push_back(trianglePrism(&local[3 * t]));
    triangle_grids_.emplace_back(local);
    walls_.push_back(w);
    double extent = 0.0;
    for (const Vec3& v : local) extent = std::max(extent, norm(v));
    wall_extent_.push_back(extent);
    setWallMotion(nWalls() - 1, motion);
    walls_.back().initial_origin = motion.translation;
    lists_valid_ = false;
    return nWalls() - 1;
}

// The forces of the last step stay valid when the wall's motion is set to what it
// already is (a solver re-asserting its plate speeds every step): the wall contacts'
// dashpots and friction see the wall velocity, so any change makes them stale and the
// next step re-evaluates them first.
void DemModel::setWallVelocity(int wall, const Vec3& velocity, const Vec3& angular_velocity)
{
    WallState& w = walls_.at(wall);
    if (w.velocity == velocity && w.angular_velocity == angular_velocity) return;
    w.velocity = velocity;
    w.angular_velocity = angular_velocity;
    forces_valid_ = false;
}

void DemModel::setWallMotion(int wall, const WallMotion& motion)
{
    WallState& w = walls_.at(wall);
    const Quat orientation = normalised(motion.orientation);
    if (w.origin == motion.translation && w.orientation == orientation && w.velocity == motion.velocity &&
        w.angular_velocity == motion.angular_velocity)
        return;
    w.origin = motion.translation;
    w.orientation = orientation;
    w.velocity = motion.velocity;
    w.angular_velocity = motion.angular_velocity;
    forces_valid_ = false;
}

void DemModel::setWallState(int wall, const WallState& state)
{
    walls_.at(wall) = state;
    lists_valid_ = forces_valid_ = false;
}

WallPose DemModel::wallPose(const WallState& w) const
{
    WallPose pose;
    pose.kind = w.kind;
    pose.origin = w.origin;
    pose.rotation = rotationMatrix(w.orientation);
    pose.velocity = w.velocity;
    pose.angular_velocity = w.angular_velocity;
    pose.normal = w.normal;
    pose.first_triangle = w.first_triangle;
    pose.n_triangles = w.n_triangles;
    return pose;
}

void DemModel::moveWalls(double dt)
{
    for (WallState& w : walls_) {
        w.origin += dt * w.velocity;
        w.orientation = normalised(quatFromRotationVector(dt * w.angular_velocity) * w.orientation);
    }
}

}  // namespace rockfrac

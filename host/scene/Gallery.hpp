// The built-in scene, modelled on Chow 2005's test world: a walkable gallery
// of 3 x 2 rooms (8 m square, 3 m high) with doorways, partitions, pillars,
// floor and ceiling, framed pictures on the walls, and exhibits on plinths
// -- real models from Debian's glmark2-data and assimp-testmodels when they
// are installed (a sphere stands in for each missing one, and the scene's
// notes say so). Room (i, k) is centred at (8 i, 0, -8 k); the floor is y = 0.
#pragma once
#include <string>
#include <vector>

#include "Scene.hpp"

namespace arp::host {

// `model_roots`: where to look for the exhibit models (default: the Debian package folders).
Scene make_gallery(const std::vector<std::string>& model_roots = {});

// A walk through every room at eye height 1.6 m, through the doorways, back to the start.
std::vector<glm::dvec3> gallery_walk();

}  // namespace arp::host

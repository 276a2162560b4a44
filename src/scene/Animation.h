// glTF animations played on the scene model: node translation, rotation and scale channels
// with step, linear (slerp for rotations) and cubic-spline interpolation (glTF 2.0 section
// 3.11 and its Appendix C), all animations together, looping over the longest one.
// poseScene moves the instances of animated nodes; everything else is static. Lights and
// cameras stay where the file puts them.
#pragma once

#include "scene/Scene.h"

namespace gi::scene {

// The value of one channel at `seconds` (clamped to its first and last key).
[[nodiscard]] glm::vec4 sampleChannel(const AnimationChannel& channel, float seconds);

// The longest animation's duration (0 without animations).
[[nodiscard]] float animationDuration(const Scene& scene);

// Marks the instances whose node or an ancestor is the target of a channel as dynamic.
void markDynamicInstances(Scene& scene);

// Moves every dynamic instance to its pose at `seconds` (looping over animationDuration),
// minus scene.origin. Static instances are not touched.
void poseScene(Scene& scene, double seconds);

// The bounds of the scene over its whole animation, sampled at `samples` times (and the rest
// pose): what cascades, atlases and shadow maps must cover so that they need not move.
[[nodiscard]] Aabb animatedBounds(const Scene& scene, int samples = 64);

} // namespace gi::scene

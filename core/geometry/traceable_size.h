#pragma once

namespace caustica {

// The sizes caustica traces in single precision: shapes (and a lens's
// edge) within kFarthestFromCamera of the camera, which render space is
// centred on, and scenes spanning at least kSmallestSceneSize. Beyond
// them, squared lengths and Embree's intersection arithmetic leave float's
// range (measured: a test scene renders as at unit size from about 2e-9 to
// 1e9 across; 1e-7 and 1e8 keep a margin).
inline constexpr float kFarthestFromCamera = 1e8f, kSmallestSceneSize = 1e-7f;

}  // namespace caustica

// The randomised synthetic RGB-D scenes over real data (host only, cuetrack_recorded_cv):
// drawScene (drivers/synth) with the real Kinect stills of DATA/kinect-stills offered as
// backdrops and textures cut from the development videos of DATA/otb (the ground-truth
// box of a drawn frame: a real object's look). Spec (openFrameSource; parsed by
// rec::parseRandomSpec):
//   rand:SEED:DATA   DATA is the shared data folder (../shared/data)
//   rand:SEED        (no DATA; any build) the generated room and procedural textures
// SEED draws the scene; SourceOptions::seed draws the sensor noise, as for synth:.
// Named rand-SEED (the room), rand-SEED-nyuN or rand-SEED-tumN (the still behind it).
#pragma once

#include <memory>

#include "cuetrack/drivers/SceneReader.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

class RandomSceneReader final : public SceneReader {
 public:
  RandomSceneReader();
  ~RandomSceneReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});

 private:
  struct Data;
  std::unique_ptr<Data> _data;  // the chosen still's colour and every still's depth
};

}  // namespace cuetrack

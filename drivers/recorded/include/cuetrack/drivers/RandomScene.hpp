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
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

class SyntheticSource;

class RandomSceneReader final : public FrameSource {
 public:
  RandomSceneReader();
  ~RandomSceneReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override;
  double nominalFps() const override;
  const SyntheticSource* scene() const { return _scene.get(); }

 private:
  struct Data;
  std::unique_ptr<Data> _data;  // the chosen still's colour and every still's depth
  std::unique_ptr<SyntheticSource> _scene;
  std::string _name;
  char _error[768] = "";
};

}  // namespace cuetrack

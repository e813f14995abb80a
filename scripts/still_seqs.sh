# The still: sequences (docs/recordings.md): synthetic scenes' objects rendered into the
# real Kinect stills of $SHARED/data/kinect-stills, with exact ground truth. Sourced by
# scripts/devset.sh and scripts/benchmarks.sh (the same list is checked to keep the target
# in view by test_drivers_opencv). Sets still_seqs, empty when the stills are absent.
#   flat-turn  a book turning face-on -> 78 degrees, 100 mm before the TUM desk's monitor
#   occlusion  a cylinder 60 mm before the back of the NYU armchair; a striped board passes
#              in front (hidden ~1 s)
#   turn       a box turning side-on -> end-on before the NYU sideboard (150 mm side-on,
#              ~10 mm end-on)
#   held       a target carried with a hand over the TUM desk, in front of the monitor and
#              partly behind it (300 mm before it at the motion's centre)
STILLS="$SHARED/data/kinect-stills"
NYU="$STILLS/nyu-joinmap"
TUM="$STILLS/tum-fr1"
nyu_k=518,519,325.5,253.5
tum_k=517.3,516.5,318.6,255.3,0.2  # freiburg1; depth value / 5 = mm
still_seqs=()
if [ -d "$NYU" ] && [ -d "$TUM" ]; then
  still_seqs=("still:$TUM/1.png,$TUM/1_depth.png,$tum_k:flat-turn@260,170,100"
              "still:$NYU/color/5.png,$NYU/depth/5.pgm,$nyu_k:occlusion@370,200,60"
              "still:$NYU/color/3.png,$NYU/depth/3.pgm,$nyu_k:turn@170,320,150"
              "still:$TUM/1.png,$TUM/1_depth.png,$tum_k:held@300,180,300")
fi

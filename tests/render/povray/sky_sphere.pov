#include "camera_stage.inc"
sky_sphere {
    pigment { gradient y color_map { [0 rgb <0.9, 0.75, 0.6>] [0.3 rgb <0.5, 0.6, 0.85>] [1 rgb <0.1, 0.2, 0.6>] } }
    pigment { radial frequency 6
              color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 0.9, 0.8, 0.4>] [1 rgbt <1, 0.9, 0.8, 0.4>] }
              rotate <0, 10, 0> }
}
camera { location <0.0137, 0.8, -5> direction z * 0.5 / tan(radians(90 / 2)) up y right x * image_width / image_height
         look_at <0.0137, 2.2, 0.8> }

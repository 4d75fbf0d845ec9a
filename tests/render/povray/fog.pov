#include "camera_stage.inc"
fog { distance 6 color rgb <0.7, 0.7, 0.75> }
camera { location <0.0137, 2.0291, -5> direction z * 0.5 / tan(radians(50 / 2)) up y right x * image_width / image_height
         look_at <0.0137, 0.5291, 0.8> }

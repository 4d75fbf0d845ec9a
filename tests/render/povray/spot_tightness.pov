#declare NoSun = 1;
#include "camera_stage.inc"
light_source { <0.3, 5, -1> color rgb <1.6, 1.5, 1.3> spotlight point_at <-0.2, 0, 0.8> radius 15 falloff 30 tightness 6 }
camera { location <0.0137, 4.0291, -5> direction z * 0.5 / tan(radians(50 / 2)) up y right x * image_width / image_height
         look_at <0.0137, 0.5291, 0.8> }

#include "camera_stage.inc"
light_source { <-4, 3, -2> color rgb <0.4, 0.35, 0.3> shadowless }
camera { location <0.0137, 4.0291, -5> direction z * 0.5 / tan(radians(50 / 2)) up y right x * image_width / image_height
         look_at <0.0137, 0.5291, 0.8> }

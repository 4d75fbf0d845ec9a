#include "camera_stage.inc"
fog { fog_type 2 distance 2 color rgbt <0.85, 0.85, 0.9, 0.2> fog_offset 0.3 fog_alt 0.4 }
camera { location <0.0137, 2.0291, -5> direction z * 0.5 / tan(radians(50 / 2)) up y right x * image_width / image_height
         look_at <0.0137, 0.5291, 0.8> }

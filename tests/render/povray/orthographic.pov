#include "camera_stage.inc"
camera { orthographic location <3.0137, 5.0291, -6> right x * 6 up y * 6 look_at <0.0137, 0.5291, 1> }

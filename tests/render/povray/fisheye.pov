#include "camera_stage.inc"
camera { fisheye location <0.0137, 1.5291, -2.5> angle 180 right x * image_width / image_height up y look_at <0.0137, 0.8291, 1> }

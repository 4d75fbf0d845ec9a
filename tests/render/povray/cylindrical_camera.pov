#include "camera_stage.inc"
// POV-Ray's vertical extent is the length of up: crtc keeps the middle's pixels square, so
// up is the angle across in radians over the image's proportions.
camera { cylinder 1 location <0.0137, 1.2291, -1.5> angle 200 right x up y * radians(200) * image_height / image_width
         look_at <0.0137, 1.2291, 1> }

// Quality benchmark: depth of field (see bench/README.md, "Render time against error").
// Equivalent to dof.crt, shading matched as in bench/render/. POV-Ray's focal blur moves
// the eye by aperture / 2 times points of a disc of radius 1/2, so crtc's lens radius
// 150 / 1000 = 0.15 is aperture 0.6 here (a converged render of each agrees to 0.7/255
// RMSE, and 0.55 or 0.65 agree less). The focal point lies on the view axis, 6 units from
// the eye, as crtc's focaldistance 6. run.sh sets Blur (blur_samples) and Variance
// (0: every pixel takes all its samples).
#version 3.7;
#ifndef (Blur) #declare Blur = 64; #end
#ifndef (Variance) #declare Variance = 1 / 128; #end
#ifndef (Confidence) #declare Confidence = 0.9; #end
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.15
    max_trace_level 4
    adc_bailout 0
}

#declare Eye = <0.0, 1.5, -6.0>;
#declare Target = <0.0, 0.8, 0.0>;
#declare VFov = 40;
camera {
    perspective
    location Eye
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at Target
    aperture 0.6
    blur_samples Blur
    focal_point Eye + vnormalize(Target - Eye) * 6.0
    confidence Confidence
    variance Variance
}

light_source { <-3.0, 6.0, -5.0> color rgb 1 }

background { color rgb <0.55, 0.65, 0.85> }

plane {
    y, 0
    texture { pigment { color rgb <0.8, 0.8, 0.75> } finish { ambient 1 diffuse 1 } }
}

#for (I, 0, 6)
    sphere {
        <-3.0 + I * 1.0, 0.5, -3.0 + I * 1.5>, 0.5
        texture {
            pigment { color rgb <0.9 - I * 0.1, 0.3 + I * 0.08, 0.2 + I * 0.1> }
            finish { ambient 1 diffuse 1 }
        }
    }
#end

// The reference room (scenes/reference-room.scene.json) for POV-Ray 3.7: the timing yardstick.
//
// Render as tests/bench/povray-reference-room.sh does:
//   povray +W1280 +H720 -D -A +WT2 +O/tmp/reference-room-pov.png tests/bench/reference-room.pov
//
// Conversion rules, so the two renderers do the same work:
// - Coordinates: RayStudio is right-handed (camera looks down -z), POV-Ray left-handed
//   (looks down +z). Every point here is the scene file's point with z negated; +x stays right.
// - Camera: POV's `angle` is the horizontal field of view across `right`. Our fov_y = 55 at
//   16:9 gives 2 * atan(tan(27.5 deg) * 16/9) = 85.5656 deg.
// - Depth: our max_depth 3 counts bounces after the primary hit; POV's max_trace_level
//   counts the primary ray as level 1 (level 1 shows mirrors black), so 3 bounces = level 4.
//   adc_bailout 0 keeps POV from cutting weak rays short, as our Whitted tracer never does.
// - Lighting: one point light, no fade (no fall-off in both). Our ambient term is
//   ambient * color * diffuse; with ambient_light 1 each finish's `ambient` is that product.
// - Materials: ours weight the local term by (1 - reflectivity - transparency). POV adds
//   reflection on top, so diffuse/phong/ambient are pre-multiplied by (1 - reflectivity);
//   transmit already removes its share of the local term. phong/phong_size are our
//   specular/shininess (both use (R.V)^n with the light's colour). Glass: ior via interior,
//   `reflection { 0, t fresnel on }` + conserve_energy is t * (F * reflected + (1-F) *
//   refracted), with POV's exact Fresnel where we use Schlick's approximation.
// - Shadows: ours treat glass as opaque. POV would let light through a transmitting
//   object, so the glass ball itself casts no shadow and an invisible opaque twin casts it.
#version 3.7;

global_settings {
    assumed_gamma 1.0
    max_trace_level 4
    adc_bailout 0
    ambient_light rgb 1
}

background { rgb <0, 0, 0> }

camera {
    perspective
    location <0, 3, -2.5>
    look_at <0, 2.1, 6>
    sky <0, 1, 0>
    right x * 1280 / 720
    up y
    angle 85.5656
}

// "ceiling light": point, white, intensity 1, no fall-off.
light_source { <0, 5.3, 4.5> rgb <1, 1, 1> }

// Materials: name as in the scene file; ambient = 0.08 * color * diffuse * (1 - reflectivity).
#declare WhiteWall = texture {
    pigment { rgb <0.8, 0.78, 0.74> }
    finish { ambient rgb <0.0576, 0.05616, 0.05328> diffuse 0.9 phong 0 }
}
#declare RedWall = texture {
    pigment { rgb <0.75, 0.12, 0.1> }
    finish { ambient rgb <0.054, 0.00864, 0.0072> diffuse 0.9 phong 0 }
}
#declare TealWall = texture {
    pigment { rgb <0.08, 0.5, 0.55> }
    finish { ambient rgb <0.00576, 0.036, 0.0396> diffuse 0.9 phong 0 }
}
#declare PolishedFloor = texture {  // reflectivity 0.15
    pigment { rgb <0.7, 0.66, 0.6> }
    finish {
        ambient rgb <0.04046, 0.038148, 0.03468> diffuse 0.7225 phong 0.255 phong_size 50
        reflection { 0.15 }
    }
}
#declare Mirror = texture {  // reflectivity 0.85
    pigment { rgb <0.95, 0.95, 0.95> }
    finish {
        ambient rgb <0.00114, 0.00114, 0.00114> diffuse 0.015 phong 0.12 phong_size 200
        reflection { 0.85 }
    }
}
#declare Glass = material {  // transparency 0.9, ior 1.5
    texture {
        pigment { rgbt <1, 1, 1, 0.9> }
        finish {
            ambient 0 diffuse 0 phong 1 phong_size 200
            reflection { 0, 0.9 fresnel on } conserve_energy
        }
    }
    interior { ior 1.5 }
}
#declare OrangePlastic = texture {
    pigment { rgb <0.95, 0.42, 0.08> }
    finish { ambient rgb <0.0646, 0.02856, 0.00544> diffuse 0.85 phong 0.6 phong_size 60 }
}
#declare BluePlastic = texture {
    pigment { rgb <0.12, 0.25, 0.85> }
    finish { ambient rgb <0.00816, 0.017, 0.0578> diffuse 0.85 phong 0.7 phong_size 120 }
}
#declare YellowPlastic = texture {
    pigment { rgb <0.95, 0.78, 0.12> }
    finish { ambient rgb <0.0646, 0.05304, 0.00816> diffuse 0.85 phong 0.5 phong_size 40 }
}
#declare GreenMatte = texture {
    pigment { rgb <0.2, 0.65, 0.22> }
    finish { ambient rgb <0.0144, 0.0468, 0.01584> diffuse 0.9 phong 0 }
}
#declare Chalk = texture {
    pigment { rgb <0.9, 0.9, 0.88> }
    finish { ambient rgb <0.0648, 0.0648, 0.06336> diffuse 0.9 phong 0 }
}

// The 6 planes: floor y=0, ceiling y=6, back z=-12 (POV +12), front z=4 (POV -4, behind
// the camera), left x=-5, right x=5. Normals point into the room.
plane { y, 0 texture { PolishedFloor } }   // floor
plane { -y, -6 texture { WhiteWall } }     // ceiling
plane { -z, -12 texture { WhiteWall } }    // back wall
plane { z, -4 texture { WhiteWall } }      // front wall
plane { x, -5 texture { RedWall } }        // left wall
plane { -x, -5 texture { TealWall } }      // right wall

// The 8 spheres.
sphere { <-2.9, 1.4, 8.6>, 1.4 texture { Mirror } }          // mirror ball
sphere { <0.9, 1.0, 4.2>, 1.0 material { Glass } no_shadow }  // glass ball
sphere { <0.9, 1.0, 4.2>, 0.999 pigment { rgb 0 } no_image no_reflection }  // its opaque shadow
sphere { <1.6, 0.7, 7.5>, 0.7 texture { OrangePlastic } }    // orange ball
sphere { <-0.9, 0.8, 5.6>, 0.8 texture { BluePlastic } }     // blue ball
sphere { <3.3, 1.1, 9.5>, 1.1 texture { GreenMatte } }       // green ball
sphere { <-3.6, 0.5, 4.5>, 0.5 texture { Chalk } }           // chalk ball
sphere { <2.9, 0.45, 3.4>, 0.45 texture { Mirror } }         // chrome ball
sphere { <-0.2, 3.4, 9.6>, 0.9 texture { YellowPlastic } }   // floating ball

// SPDX-License-Identifier: MIT
// cup.pov (tests/optics/optics.sh, check "coffee cup"): the reflective
// caustic of a ring. A mirror ring (inner radius 1, rim 0.5 high, a
// perfect grey mirror) stands on a white floor, lit over its rim by a
// parallel light at ALT degrees above the horizon coming from -x, or
// (DIST > 0) by a point light at (-DIST, DIST tan ALT, 0). The wall is
// vertical, so each reflected ray's path seen from above is the 2D
// reflection in a circle: the floor inside the ring shows the caustic of
// the circle (for parallel light the nephroid, its cusp on the axis R/2
// from the centre; for a point source the cusp where the mirror
// equation puts the image). The light keeps its elevation low and the
// rim low (ALT 20, rim 0.5) so that the paraxial rays meet the far wall
// below the rim at every height from 0 to 0.5 (rays over the near rim
// fall 2 tan 20 = 0.73 crossing the ring) and reach the floor once,
// without a second reflection. Floor inside the ring: direct light only
// where the near wall does not shade it, photons from the wall.
#version 3.7;
#ifndef (ALT) #declare ALT = 20; #end
#ifndef (DIST) #declare DIST = 0; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.004 autostop 0 }
}
// looking down at the floor inside the ring, x in [-1, 1] (rows, top row
// x = +1, the far wall), z in [-1, 1] (columns)
camera { orthographic location <0, 0.05, 0> direction <0, -1, 0>
  right <0, 0, 2> up <2, 0, 0> }
#if (DIST = 0)
light_source { <-cos(radians(ALT)), sin(radians(ALT)), 0> * 100 color rgb 1
  parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
#else
light_source { <-DIST, DIST * tan(radians(ALT)), 0> color rgb 1
  photons { refraction on reflection on }
}
#end
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
difference {
  cylinder { <0, 0, 0>, <0, 0.5, 0>, 1.05 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 1 }
  pigment { color rgb 0 }
  finish { ambient 0 diffuse 0 reflection rgb 1 }
  photons { target reflection on collect off }
}

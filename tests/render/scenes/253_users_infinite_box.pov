// SPDX-License-Identifier: MIT
// A box corner at infinity ('Count / clock' at clock 0, poliana-girl's
// aug31): POV-Ray 3.7 takes the corner as it is and its box intersection
// stops at BOUND_HUGE (2e10), so the box runs out of sight; iris refused
// the scene ("not a finite number") before session 12 and now takes the
// corner as +-1e7 (POV-Ray's MAX_DISTANCE; at 2e10 iris's arithmetic
// loses precision: 25 dB here). A pillar rising for ever (tilted and
// moved, so the corner goes through a transform), a translucent slab
// running away behind, and a bar whose x runs both ways.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 1.5, 0> angle 60 }
light_source { <-4, 10, -8> rgb 1 }
background { rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
#declare Zero = 0;
box { <-0.5, 0, -0.5>, <0.5, 1 / Zero, 0.5>
      pigment { rgb <1, 0.5, 0.2> } rotate 10 * z translate -2 * x }
box { <0.5, 0.2, 1 / Zero>, <2.5, 1.5, -1>
      pigment { rgb <0.2, 0.8, 0.4> transmit 0.5 } }
box { <-(1 / Zero), 2.6, 4>, <1 / Zero, 3, 5> pigment { rgb <0.9, 0.9, 0.2> } }

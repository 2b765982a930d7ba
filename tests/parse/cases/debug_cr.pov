// options: -q
// '\r' in the debug stream: POV-Ray 3.7 ends a line there, so "\r\n"
// is two line breaks. The .expect file is POV-Ray 3.7.0.10's own #debug
// output for this file (checked: identical, byte for byte with od -c).
#version 3.7;
global_settings { assumed_gamma 1 }
#debug "a\rb\n"
#debug "c\r"
#debug "d\r\ne\n"
#debug concat("f", chr(13), chr(13))
#debug "end\n"
camera { location <0,0,-5> look_at 0 }

// expect: 2 3
#version 3.7;
#include "self_include.pov"

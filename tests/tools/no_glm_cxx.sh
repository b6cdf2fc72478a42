#!/bin/sh
# A C++ compiler on a machine without GLM's headers, as g++ answers there: proceduray-field's
# test that the message names GLM and the fix, not the user's field.
echo "field.cpp:1:10: fatal error: glm/glm.hpp: No such file or directory" >&2
echo "compilation terminated." >&2
exit 1

// Spheres are round in millimetres (model::Sphere): a radius counts voxels along the scan's
// finest axis, and a step along axis a is sphereScale[a] of those (model::sphereScale; 1, 1, 1
// on an isotropic scan). The host sets sphereScale once for every solver program.
uniform vec3 sphereScale;

// The offset's length in a sphere radius's units.
float sphereNorm(vec3 offset) { return length(offset * sphereScale); }

// Signed distance from the sphere's surface in voxel steps, to first order (negative inside):
// the twin of model::sphereDistance.
float sphereDistance(vec3 offset, float radius) {
    float n = sphereNorm(offset);
    float g = n > 0.0 ? length(offset * sphereScale * sphereScale) / n
                      : max(sphereScale.x, max(sphereScale.y, sphereScale.z));
    return (n - radius) / g;
}

// Whether a correction's reach (centre xyz, radius w in voxels; model::Reach) takes in p;
// radius <= 0: everywhere.
bool inReach(vec3 p, vec4 sphere) {
    return sphere.w <= 0.0 || sphereNorm(p - sphere.xyz) <= sphere.w;
}

// Shadow map fragment stage. Point lights store the distance to the light in an R32F
// cube face; directional and spot lights need only the depth attachment.
in vec3 vWorldPos;
uniform vec3 lightPos;
uniform int storeDistance;
layout(location = 0) out float outDistance;
void main() {
    outDistance = storeDistance != 0 ? length(vWorldPos - lightPos) : 0.0;
}

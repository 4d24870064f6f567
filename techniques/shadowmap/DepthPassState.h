#pragma once
// The GL state of a depth-map pass, set for a scope and restored at its end: the viewport of the map,
// colour writes off (the pass writes depth only) and glPolygonOffset as the constant and slope-scaled
// bias. Every depth-map member of the family (`shadowmap`, `pcss`, `cascaded`, `cubemap`, `paraboloid`)
// renders its depth pass inside one, so none can forget to restore what the lighting pass relies on.
namespace sb {

class DepthPassState {
public:
    /// Viewport 0, 0, size x size; colour mask off; polygon offset fill on with (slope, constant).
    DepthPassState(int size, float biasSlope, float biasConstant);
    /// Polygon offset fill off, colour mask on.
    ~DepthPassState();
    DepthPassState(const DepthPassState&) = delete;
    DepthPassState& operator=(const DepthPassState&) = delete;
};

} // namespace sb

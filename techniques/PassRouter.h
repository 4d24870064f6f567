#pragma once
// A hook that renames a technique's passes as they begin (PassTimer): a hybrid technique
// (techniques/hybrid/) runs two techniques in one frame and records their passes under its own names
// ("self.lighting", "cast.depth"), and uses the moment a pass begins to say which instances the pass may
// shade (Submitter::setViewScope). Timed frames of every other technique run without a router.
namespace sb {

class PassRouter {
public:
    virtual ~PassRouter() = default;
    /// Called as `pass` begins: the name it is recorded under. The returned string must live for the
    /// process (the query ring keeps it by pointer and may read it after the router is gone).
    virtual const char* enter(const char* pass) = 0;
    /// The name `pass` is recorded under, without entering it (a pass the technique skips).
    virtual const char* nameOf(const char* pass) const = 0;
};

} // namespace sb

// Uses the installed tumble: a cube dropped above the ground must fall. Exit code 0 if it did.
#include <tumble/tumble.hpp>

#include <cstdio>

int main()
{
    tumble::World world{tumble::WorldSettings{}};
    world.setGround(tumble::Plane{.height = 0.0});
    const tumble::BodyId cube = world.createBody(tumble::BodyDef{.position = {0.0, 5.0, 0.0}});
    for (int i = 0; i < 240; ++i) {
        world.step(1.0 / 240.0);
    }
    const double height = world.body(cube).position.y;
    std::printf("cube height after 1 s: %.6f m\n", height);
    // it fell and hit the ground (4 m takes 0.9 s), and did not fall through it
    return height < 4.0 && height > 0.5 ? 0 : 1;
}

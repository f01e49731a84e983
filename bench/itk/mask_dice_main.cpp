// steerseg-mask-dice A B: Dice of two masks on the same grid, as one line of JSON.
#include "itk_image_io.hpp"
#include "mask_dice.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: steerseg-mask-dice MASK_A MASK_B\n");
        return 2;
    }
    try {
        using namespace steerseg::itkbench;
        const MaskImage::Pointer a = readMask(argv[1]);
        const MaskImage::Pointer b = readMask(argv[2]);
        const DiceResult r = maskDice(a, b);
        std::printf("{\"dice\": %.6f, \"a_voxels\": %lld, \"b_voxels\": %lld, \"overlap\": %lld}\n",
                    r.dice, r.aVoxels, r.bVoxels, r.overlap);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "steerseg-mask-dice: %s\n", e.what());
        return 1;
    }
}

// The id resolve of a multisampled target (src/render/targets/multisample.hpp). Cell
// ids are integers and cannot be averaged: each pixel takes the id that most
// of its samples hold. A tie (an edge through the pixel splitting its samples
// evenly, which happens when the edge passes close to the centre) goes to the
// tied id that holds more samples of the block of pixels centred on it, 3 × 3
// or, at the image's border, as much of that as is symmetric about the pixel
// (a row or column of three, or the pixel alone): for a straight edge, the
// side with more of a centrally symmetric block's area is the side of the
// centre, which the tracer's centre ray sees. A tie there too goes to the id
// of the lowest-numbered sample among those tied.
// SAMPLES (2..16) is defined when the program is built, one program per
// count, so that the loops unroll and the array stays in registers (with a
// uniform count llvmpipe spilled it and the pass cost more than the frame).
uniform usampler2DMS u_ids;

layout(location = 0) out uint o_id;

int count_in_block(ivec2 p, uint id) {
    ivec2 size = textureSize(u_ids);
    // Reach 1 along an axis only where both neighbours exist: a symmetric block.
    ivec2 reach = ivec2(p.x > 0 && p.x + 1 < size.x ? 1 : 0, p.y > 0 && p.y + 1 < size.y ? 1 : 0);
    int n = 0;
    for (int dy = -reach.y; dy <= reach.y; ++dy)
        for (int dx = -reach.x; dx <= reach.x; ++dx)
            for (int s = 0; s < SAMPLES; ++s) n += texelFetch(u_ids, p + ivec2(dx, dy), s).r == id ? 1 : 0;
    return n;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint ids[SAMPLES];
    for (int i = 0; i < SAMPLES; ++i) ids[i] = texelFetch(u_ids, p, i).r;
    uint best = ids[0];
    int best_count = 0;
    bool tie = false;
    for (int i = 0; i < SAMPLES; ++i) {
        int count = 0;
        for (int k = 0; k < SAMPLES; ++k) count += ids[k] == ids[i] ? 1 : 0;
        if (count > best_count) {
            best = ids[i];
            best_count = count;
            tie = false;
        } else if (count == best_count && ids[i] != best) {
            tie = true;
        }
    }
    if (tie) {
        // Only the ids tied at best_count compete; the first (lowest sample) wins ties again.
        uint winner = best;
        int winner_block = count_in_block(p, best);
        for (int i = 0; i < SAMPLES; ++i) {
            if (ids[i] == best) continue;
            int count = 0;
            for (int k = 0; k < SAMPLES; ++k) count += ids[k] == ids[i] ? 1 : 0;
            if (count != best_count) continue;
            int block = count_in_block(p, ids[i]);
            if (block > winner_block) {
                winner = ids[i];
                winner_block = block;
            }
        }
        best = winner;
    }
    o_id = best;
}

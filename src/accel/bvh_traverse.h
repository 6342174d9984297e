/* The hierarchy's traversals, written once and compiled by tracer.c once
 * per box test: BVH_TRAVERSE_NAME(f) names the functions, BVH_TRAVERSE_NODE_HITS
 * is the box test (bvh.h), BVH_TRAVERSE_RAY makes the ray it wants,
 * BVH_TRAVERSE_TARGET the instruction set they are
 * compiled for. No include guard: it is meant to be included twice. */

/* The nearest polygon by the hierarchy: nearer children first, those the
 * ray enters beyond the best hit so far skipped. */
BVH_TRAVERSE_TARGET static void BVH_TRAVERSE_NAME(nearest_in_bvh)(Tracer *tr, Vec3 org, Vec3 dir, double tmin,
                                                                  double plane_t, int exclude, Hit *hit, double *best)
{
    const Bvh *b = tr->bvh;
    if (b->nnodes == 0)
        return;
    RayFrame frame = ray_frame(org, dir);
    BvhRay br;
    BVH_TRAVERSE_RAY(&br, org, dir);
    Pending stack[BVH_STACK];
    int sp = 0;
    stack[sp].child = 0;
    stack[sp++].enter = 0.0;
    while (sp > 0) {
        Pending p = stack[--sp];
        double limit = hit->kind == HIT_NONE ? plane_t : *best;
        /* Entered beyond the best hit: nothing nearer inside (the test that
         * pushed it grew the limit the same way). */
        if (p.enter > limit * BVH_GROW)
            continue;
        if (!bvh_is_leaf(p.child)) {
            const BvhNode *n = &b->nodes[p.child];
            double enter[BVH_WIDTH];
            tr->stats.nodes_visited++;
            unsigned mask = BVH_TRAVERSE_NODE_HITS(n, &br, 0.0, limit, enter);
            sp = push_children(stack, sp, n, mask, enter);
            continue;
        }
        uint32_t first = bvh_leaf_first(p.child), end = first + bvh_leaf_count(p.child);
        for (uint32_t k = first; k < end; k++)
            if ((int)b->items[k] != exclude)
                try_nearer_prim(tr, &frame, k, b->items[k], tmin, plane_t, hit, best);
    }
}

/* Every polygon the segment meets, to the visitor, until it says stop
 * (trace_segment_hits); the order is the tree's, not the distance's. */
BVH_TRAVERSE_TARGET static int BVH_TRAVERSE_NAME(segment_hits_in_bvh)(Tracer *tr, const RayFrame *frame, Vec3 org,
                                                                      Vec3 dir, double tmin, double tmax, int exclude,
                                                                      unsigned hide, TraceHitVisitor visit, void *user,
                                                                      uint64_t *tests)
{
    const World *w = tr->world;
    const Bvh *b = tr->bvh;
    if (b->nnodes == 0)
        return 0;
    BvhRay br;
    BVH_TRAVERSE_RAY(&br, org, dir);
    uint32_t stack[BVH_STACK];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        uint32_t c = stack[--sp];
        if (!bvh_is_leaf(c)) {
            const BvhNode *n = &b->nodes[c];
            double enter[BVH_WIDTH];
            tr->stats.nodes_visited++;
            unsigned mask = BVH_TRAVERSE_NODE_HITS(n, &br, 0.0, tmax, enter);
            for (int k = BVH_WIDTH - 1; k >= 0; k--)
                if ((mask & (1u << k)) && n->child[k] != BVH_EMPTY)
                    stack[sp++] = n->child[k];
            continue;
        }
        uint32_t first = bvh_leaf_first(c), end = first + bvh_leaf_count(c);
        for (uint32_t k = first; k < end; k++) {
            uint32_t pi = b->items[k];
            if ((int)pi == exclude || (b->prims[k].hide & hide))
                continue;
            ++*tests;
            double t = prim_test(w, b, k, pi, frame, tmax); /* negative at tmax or beyond */
            if (t > tmin && visit(user, pi, t))
                return 1;
        }
    }
    return 0;
}

/* The hierarchy's traversals, written once and compiled by tracer.c once
 * per box test: BVH_TRAVERSE_NAME(f) names the functions, BVH_TRAVERSE_NODE_HITS
 * is the box test (bvh.h), BVH_TRAVERSE_RAY makes the ray it wants,
 * BVH_TRAVERSE_TARGET the instruction set they are
 * compiled for. No include guard: it is meant to be included twice.
 *
 * Both walk the top level and, at an instance's leaf item, its
 * prototype's hierarchy on the ray carried into its space (instance_ray:
 * the same t), naming its polygons by their ids (instance.h). */

/* The nearest polygon by hierarchy b (the top level: inst NULL; a
 * prototype's: the instance it is walked for): nearer children first,
 * those the ray enters beyond the best hit so far skipped. */
BVH_TRAVERSE_TARGET static void BVH_TRAVERSE_NAME(nearest_in_bvh)(Tracer *tr, const Bvh *b, const Instance *inst,
                                                                  Vec3 org, Vec3 dir, const double *inv, double tmin,
                                                                  double plane_t, int exclude, Hit *hit, double *best)
{
    if (b->nnodes == 0)
        return;
    const World *w = tr->world;
    /* The polygon tests' frame, made at the first leaf polygon: a walk that
     * meets only instances' boxes, or none, spares it. */
    RayFrame frame;
    int framed = 0;
    BvhRay br;
    if (inv)
        BVH_TRAVERSE_RAY_INV(&br, org, inv);
    else
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
        for (uint32_t k = first; k < end; k++) {
            uint32_t item = b->items[k];
            if (item & BVH_INSTANCE) {
                /* alone in its leaf (bvh.c), its box was the leaf's */
                if (end - first > 1 && !bvh_box_hit(&b->instance_box[6 * (item & ~BVH_INSTANCE)], &br,
                                                    hit->kind == HIT_NONE ? plane_t : *best))
                    continue;
                const Instance *in = &w->instances[item & ~BVH_INSTANCE];
                Vec3 lorg, ldir;
                double linv[3];
                tr->stats.instance_walks++;
                instance_ray(in, org, dir, &lorg, &ldir);
                instance_inverse_dir(in, br.inv, ldir, linv);
                BVH_TRAVERSE_NAME(nearest_in_bvh)(tr, &b->protos[in->prototype], in, lorg, ldir, linv, tmin, plane_t,
                                                  exclude, hit, best);
                continue;
            }
            int id = inst ? instance_polygon_id(w, inst, item) : (int)item;
            if (id == exclude || (inst && inst->hidden && tr->hide && instance_hidden(w, inst, item, tr->hide)))
                continue;
            if (!framed) {
                frame = ray_frame(org, dir);
                framed = 1;
            }
            try_nearer_prim(tr, b, &frame, k, (uint32_t)id, inst ? (int)(inst - w->instances) : -1, tmin, plane_t,
                            hit, best);
        }
    }
}

/* Every polygon the segment meets, to the visitor, until it says stop
 * (trace_segment_hits); the order is the tree's, not the distance's. */
BVH_TRAVERSE_TARGET static int BVH_TRAVERSE_NAME(segment_hits_in_bvh)(Tracer *tr, const Bvh *b, const Instance *inst,
                                                                      Vec3 org, Vec3 dir, const double *inv,
                                                                      double tmin, double tmax, int exclude,
                                                                      unsigned hide, TraceHitVisitor visit,
                                                                      void *user, uint64_t *tests)
{
    const World *w = tr->world;
    if (b->nnodes == 0)
        return 0;
    RayFrame frame; /* made at the first leaf polygon, as nearest_in_bvh's */
    int framed = 0;
    BvhRay br;
    if (inv)
        BVH_TRAVERSE_RAY_INV(&br, org, inv);
    else
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
            if (pi & BVH_INSTANCE) {
                if (end - first > 1 && !bvh_box_hit(&b->instance_box[6 * (pi & ~BVH_INSTANCE)], &br, tmax))
                    continue;
                const Instance *in = &w->instances[pi & ~BVH_INSTANCE];
                Vec3 lorg, ldir;
                double linv[3];
                tr->stats.instance_walks++;
                instance_ray(in, org, dir, &lorg, &ldir);
                instance_inverse_dir(in, br.inv, ldir, linv);
                if (BVH_TRAVERSE_NAME(segment_hits_in_bvh)(tr, &b->protos[in->prototype], in, lorg, ldir, linv, tmin,
                                                           tmax, exclude, hide, visit, user, tests))
                    return 1;
                continue;
            }
            int id = inst ? instance_polygon_id(w, inst, pi) : (int)pi;
            if (id == exclude || (b->prims[k].hide & hide) ||
                (inst && inst->hidden && hide && instance_hidden(w, inst, pi, hide)))
                continue;
            ++*tests;
            if (!framed) {
                frame = ray_frame(org, dir);
                framed = 1;
            }
            double t = bvh_item_test(w, b, k, &frame, tmax); /* negative at tmax or beyond */
            if (t > tmin) {
                tr->visiting = inst ? (int)(inst - w->instances) : -1;
                if (visit(user, (uint32_t)id, t))
                    return 1;
            }
        }
    }
    return 0;
}

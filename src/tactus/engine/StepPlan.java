package tactus.engine;

/**
 * A compiled scene: the state of every mass as flat arrays grouped by kind, the links as
 * one flat batch per kind, and the list of kernels that this scene needs, in order
 * (masses first, then interactions). A plan is rebuilt when the topology changes and its
 * kernel list is re-selected when a global effect (gravity, friction) is switched on or off.
 *
 * <p>Stepping a plan allocates nothing.
 */
public final class StepPlan {
    final int nMass;
    final double[] x;
    final double[] y;
    final double[] z;
    final double[] px;
    final double[] py;
    final double[] pz;
    final double[] fx;
    final double[] fy;
    final double[] fz;
    /** 1/M for inertial masses, 0 otherwise. */
    final double[] invM;
    /** Velocity retention per step: 1 - f/M (masses) or 1 - (Z + f)/M (oscillators). */
    final double[] dmp;
    /** K/M of oscillators. */
    final double[] stf;
    /** Rest position of oscillators. */
    final double[] rx;
    final double[] ry;
    final double[] rz;
    /** EWMA weight of input modules. */
    final double[] w;
    /** Target position of input modules. */
    final double[] tx;
    final double[] ty;
    final double[] tz;
    /** Masses of kind k occupy slots [kindStart[k], kindStart[k + 1]). */
    final int[] kindStart;
    /** Stable id of the mass in each slot. */
    final int[] massId;
    /** One batch per link kind (by ordinal), null when the scene has none of that kind. */
    final LinkBatch[] batches;
    final Medium medium;
    /** Scratch arrays (one value per mass slot) shared by the stencil-run kernels; null when there are no runs. */
    double[] sbx;
    double[] sby;
    double[] sbz;
    double[] sdd;
    double[] stx;
    double[] sty;
    double[] stz;
    /** Contact groups (broad-phase contacts), run right after the explicit Contact3D links. */
    ContactGroupKernel[] groups = new ContactGroupKernel[0];
    private Kernel[] kernels = new Kernel[0];
    private int kernelsVersion;

    StepPlan(int nMass, int[] kindStart, LinkBatch[] batches, Medium medium) {
        this.nMass = nMass;
        x = new double[nMass];
        y = new double[nMass];
        z = new double[nMass];
        px = new double[nMass];
        py = new double[nMass];
        pz = new double[nMass];
        fx = new double[nMass];
        fy = new double[nMass];
        fz = new double[nMass];
        invM = new double[nMass];
        dmp = new double[nMass];
        stf = new double[nMass];
        rx = new double[nMass];
        ry = new double[nMass];
        rz = new double[nMass];
        w = new double[nMass];
        tx = new double[nMass];
        ty = new double[nMass];
        tz = new double[nMass];
        massId = new int[nMass];
        this.kindStart = kindStart;
        this.batches = batches;
        this.medium = medium;
    }

    /**
     * Runs one simulation step: every mass kernel, then every interaction kernel. Package-private: stepping
     * goes through {@link Engine#step(int)}, which counts steps and runs the divergence guard.
     */
    void step() {
        Kernel[] ks = kernels;
        for (int i = 0; i < ks.length; i++) {
            ks[i].run();
        }
    }

    Kernel[] kernels() {
        return kernels;
    }

    int kernelsVersion() {
        return kernelsVersion;
    }

    /** @return the number of elements the plan updates per step: masses plus links (all kinds). */
    public int elementCount() {
        int n = nMass;
        for (LinkBatch b : batches) {
            if (b != null) {
                n += b.n;
            }
        }
        return n;
    }

    /** @return the number of masses in the plan. */
    public int massCount() {
        return nMass;
    }

    /** @return the names of the kernels this plan runs per step, in order, for diagnostics. */
    public String[] kernelNames() {
        String[] names = new String[kernels.length];
        for (int i = 0; i < kernels.length; i++) {
            names[i] = kernels[i].getClass().getSimpleName();
        }
        return names;
    }

    int start(MassKind k) {
        return kindStart[k.ordinal()];
    }

    int end(MassKind k) {
        return kindStart[k.ordinal() + 1];
    }

    LinkBatch batch(LinkKind k) {
        return batches[k.ordinal()];
    }

    /** Selects the kernels for the kinds present and the effects switched on. */
    void selectKernels() {
        java.util.ArrayList<Kernel> list = new java.util.ArrayList<>();
        boolean plainMasses = !medium.hasGravity() && !medium.hasFriction();
        for (MassKind k : MassKind.values()) {
            int s = start(k);
            int e = end(k);
            if (s == e) {
                continue;
            }
            list.add(MassKernels.create(k, this, s, e, plainMasses));
        }
        for (LinkKind k : LinkKind.values()) {
            LinkBatch b = batch(k);
            if (k == LinkKind.BUBBLE3D) {
                // contact groups take the place of explicit contacts: right after the Contact3D batch
                java.util.Collections.addAll(list, groups);
            }
            if (b == null || b.n == 0) {
                continue;
            }
            if (b.nIrregular > 0) {
                list.add(LinkKernels.create(b, this));
            }
            for (StencilRun run : b.runs) {
                if (sbx == null) {
                    sbx = new double[nMass];
                    sby = new double[nMass];
                    sbz = new double[nMass];
                    sdd = new double[nMass];
                    stx = new double[nMass];
                    sty = new double[nMass];
                    stz = new double[nMass];
                }
                list.add(new StencilKernel(run, this));
            }
        }
        kernels = list.toArray(new Kernel[0]);
        kernelsVersion++;
    }
}

package tactus.hapticstability;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiPredicate;
import java.util.function.Function;

/** Runs the adversarial suite's cases for a test and lists, as table rows, those a test's own criterion rejects. */
final class AdversarialChecks {
    private AdversarialChecks() {
    }

    /** True if the run gave the hand at most the suite's tolerance, stepped the force within its limit and refused no tick. */
    static boolean passiveWithoutBuzz(AdversarialRig.Result r) {
        return r.failure == null && r.faultTicks == 0 && r.maxEnergyToHand <= AdversarialSuite.ENERGY_TOLERANCE
                && AdversarialSuite.withinStepLimit(r.forceStep);
    }

    /** The rows (labelled) of the cases whose run fails {@code ok}; each case is run once by {@code run}. */
    static List<String> rejected(List<AdversarialCase> cases, Function<AdversarialCase, AdversarialRig.Result> run,
                                 BiPredicate<AdversarialCase, AdversarialRig.Result> ok, String label) {
        List<String> bad = new ArrayList<>();
        for (AdversarialCase c : cases) {
            AdversarialRig.Result r = run.apply(c);
            if (!ok.test(c, r)) {
                bad.add(AdversarialSuite.row(label, r) + (r.failure != null ? " " + r.failure : ""));
            }
        }
        return bad;
    }
}

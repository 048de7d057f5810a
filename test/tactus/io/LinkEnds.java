package tactus.io;

import java.lang.reflect.Method;
import tactus.PhysicalModel;

/**
 * Test helper (not a test class): the two mass names of the interaction at an index. It uses the
 * model's by-index calls getLinkMat1NameAt / getLinkMat2NameAt where they exist (needed once
 * interaction names can repeat) and the by-name getLinkMatNames otherwise.
 */
public final class LinkEnds {
    private LinkEnds() {
    }

    public static String[] of(PhysicalModel m, int i) {
        try {
            Method a = PhysicalModel.class.getMethod("getLinkMat1NameAt", int.class);
            Method b = PhysicalModel.class.getMethod("getLinkMat2NameAt", int.class);
            String first = (String) a.invoke(m, i);
            String second = (String) b.invoke(m, i);
            return new String[] {first, second.isEmpty() ? first : second};
        } catch (NoSuchMethodException e) {
            return m.getLinkMatNames(m.getLinkNameAt(i));
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }
}

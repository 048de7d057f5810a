package tactus.demo;

import ddf.minim.AudioListener;

/**
 * Keeps the first samples an {@code AudioOutput} computes (its left channel, or its only one) in an array
 * allocated up front: called on the audio thread once per buffer, it copies and counts, nothing else.
 */
final class AudioCapture implements AudioListener {
    private final float[] samples;
    private volatile int count;

    /** @param capacity the number of samples kept */
    AudioCapture(int capacity) {
        samples = new float[capacity];
    }

    @Override
    public void samples(float[] mono) {
        int n = count;
        int k = Math.min(mono.length, samples.length - n);
        if (k > 0) {
            System.arraycopy(mono, 0, samples, n, k);
            count = n + k;
        }
    }

    @Override
    public void samples(float[] left, float[] right) {
        samples(left);
    }

    /** @return the number of samples kept so far (any thread). */
    int count() {
        return count;
    }

    /** @return true once the array is full. */
    boolean isFull() {
        return count == samples.length;
    }

    /** @return the samples kept (the array itself: read it after the output is closed). */
    float[] samples() {
        return samples;
    }
}

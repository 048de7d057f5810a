package tactus.soak;

import ddf.minim.AudioListener;

/**
 * Listens to the output on Minim's own output thread: counts blocks and samples, reports the first NaN or
 * infinite sample of each block, and counts late blocks. A block is late when it arrives after everything
 * written before it has played ({@code now > clock start + blocks so far x block period}): the line ran dry, an
 * audible gap. Like the line, the clock then restarts. It also remembers which thread calls it, so that the
 * soak can tell when that thread has died.
 */
final class AudioWatch implements AudioListener {
    private final SoakReport report;
    private final long periodNanos;
    private volatile Thread audioThread;
    private volatile long lastBlockNanos;
    private long clockStart = -1;
    private long blocksSinceStart;
    private long firstBlockNanos;

    AudioWatch(SoakReport report, int bufferSize, float sampleRate) {
        this.report = report;
        this.periodNanos = Math.round(bufferSize * 1e9 / sampleRate);
    }

    @Override
    public void samples(float[] mono) {
        block(mono, null);
    }

    @Override
    public void samples(float[] left, float[] right) {
        block(left, right);
    }

    private void block(float[] a, float[] b) {
        long now = System.nanoTime();
        if (audioThread == null) {
            audioThread = Thread.currentThread();
        }
        lastBlockNanos = now;
        long n = report.audioBlocks.incrementAndGet();
        if (firstBlockNanos != 0 && now - firstBlockNanos <= SoakReport.WARM_UP_NANOS) {
            report.blocksInWarmUp = n;
        }
        report.audioSamples.addAndGet(a.length);
        if (clockStart < 0) {
            clockStart = now;
            firstBlockNanos = now;
            blocksSinceStart = 0;
        } else if (now > clockStart + blocksSinceStart * periodNanos) {
            report.lateBlocks.incrementAndGet();
            if (now - firstBlockNanos > SoakReport.WARM_UP_NANOS) {
                report.lateBlocksAfterWarmUp.incrementAndGet();
            } else {
                report.blocksInWarmUp = report.audioBlocks.get();
            }
            long late = now - (clockStart + blocksSinceStart * periodNanos);
            if (late > report.worstLateNanos) {
                report.worstLateNanos = late;
            }
            clockStart = now;
            blocksSinceStart = 0;
        }
        blocksSinceStart++;
        checkFinite(a, "left");
        if (b != null) {
            checkFinite(b, "right");
        }
    }

    private void checkFinite(float[] s, String channel) {
        for (int i = 0; i < s.length; i++) {
            if (!Float.isFinite(s[i])) {
                report.nan("audio output", "sample " + s[i] + " in the " + channel + " channel of block "
                        + report.audioBlocks.get());
                return;
            }
        }
    }

    /** @return Minim's output thread, once it has delivered a block; null before. */
    Thread audioThread() {
        return audioThread;
    }

    /** @return when the last block arrived (System.nanoTime), 0 before the first. */
    long lastBlockNanos() {
        return lastBlockNanos;
    }
}

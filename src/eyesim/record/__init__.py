"""Recording runs: MCAP recordings (Recorder, Recording), trajectory CSV, final LCD images.

    from eyesim.record import Recorder
    with Recorder(sim, "run.mcap"):
        sim.run(until=10)

See docs/recording.md."""

from eyesim.record.lcd_images import save_lcd_images
from eyesim.record.mcap_recorder import Recorder
from eyesim.record.recording import Recording, RecordingError
from eyesim.record.trajectory_csv import TrajectoryRecorder

__all__ = ["Recorder", "Recording", "RecordingError", "TrajectoryRecorder", "save_lcd_images"]

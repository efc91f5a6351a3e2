"""RoBIOS LCD group: text printing, clearing and the soft-key menu."""

from eyesim.commands.errors import require
from eyesim.robot.components.lcd import Lcd


def _lcd(robot) -> Lcd:
    return require(robot.component(Lcd), robot, "LCD")


def lcd_printf(sim, robot, request):
    (text,) = request.args
    _lcd(robot).print(text)
    return (0,)


def lcd_set_printf(sim, robot, request):
    row, column, text = request.args
    lcd = _lcd(robot)
    lcd.set_position(row, column)
    lcd.print(text)
    return (0,)


def lcd_clear(sim, robot, request):
    _lcd(robot).clear()
    return (0,)


def lcd_menu(sim, robot, request):
    _lcd(robot).set_menu(list(request.args))
    sim.events.menu(robot)
    return (0,)


HANDLERS = {
    "LCD_PRINTF": lcd_printf,
    "LCD_SET_PRINTF": lcd_set_printf,
    "LCD_CLEAR": lcd_clear,
    "LCD_MENU": lcd_menu,
}

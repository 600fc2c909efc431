/* quiet.c -- does nothing: a control board that leaves every pin alone
 * (tests/hil_sim/test_ir_receiver_state.py). */
int main(void)
{
	for (;;)
		;
}
